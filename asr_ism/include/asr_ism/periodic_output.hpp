#pragma once

#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <utility>

#include "asr_ism/background_worker.hpp"

namespace asr_ism {

/// An output published once per period (a node's timer) whose results may take longer than a
/// period to compute: each tick starts computing the newest input on a BackgroundWorker unless
/// the last computation still runs, and then publishes the last result again, so the output keeps
/// its period while its content lags (a result stands until the next is computed, so it is up to
/// two computations old when last published). A result is published as soon as it is
/// computed (`fresh`); a refused input (no result, or an exception) publishes nothing and leaves
/// nothing to publish again.
template <typename Result>
class PeriodicOutput {
 public:
  using Publish = std::function<void(const Result& result, bool fresh)>;
  using Compute = std::function<std::optional<Result>()>;

  /// `publish` is called on the worker's thread for fresh results and on the ticking thread for
  /// repeats, never twice at once and in the order of the results; `on_error` gets what a
  /// computation threw.
  PeriodicOutput(Publish publish, std::function<void(std::exception_ptr)> on_error)
      : publish_(std::move(publish)), worker_(std::move(on_error)) {}

  /// One period. A repeat is skipped where a fresh result came out since the last tick.
  void tick(Compute compute) {
    const bool started =
        worker_.tryStart([this, compute = std::move(compute)] { computeAndPublish(compute); });
    std::lock_guard<std::mutex> lock(mutex_);
    if (!started && last_ && !published_since_tick_)
      publish_(*last_, false);
    published_since_tick_ = false;
  }

  /// Blocks until no computation runs.
  void waitUntilIdle() { worker_.waitUntilIdle(); }

 private:
  void computeAndPublish(const Compute& compute) {
    std::optional<Result> result;
    try {
      result = compute();
    } catch (...) {
      forgetLast();
      throw;  // to the worker's on_error
    }
    if (!result) {
      forgetLast();
      return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    publish_(*result, true);
    published_since_tick_ = true;
    last_ = std::move(result);
  }

  void forgetLast() {
    std::lock_guard<std::mutex> lock(mutex_);
    last_.reset();
  }

  Publish publish_;
  std::mutex mutex_;  // last_, published_since_tick_, and one publish_ at a time
  std::optional<Result> last_;
  bool published_since_tick_ = false;
  BackgroundWorker worker_;  // last: destroyed first, while what a computation uses exists
};

}  // namespace asr_ism
