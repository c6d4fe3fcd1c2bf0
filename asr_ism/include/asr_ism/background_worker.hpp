#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace asr_ism {

/// Runs one job at a time on a thread of its own, so that a caller with a period to keep (a
/// node's timer) hands long work off and goes on. A job offered while one runs is refused, not
/// queued: the caller offers its newest work at its next turn, so nothing stale piles up. If the
/// thread cannot be created (a memory or process limit), jobs run on the offering thread.
class BackgroundWorker {
 public:
  /// `on_error` is called, on the thread that ran the job, with what a job threw; the worker
  /// goes on with the next job.
  explicit BackgroundWorker(std::function<void(std::exception_ptr)> on_error);
  /// Waits for the running job, then ends the thread.
  ~BackgroundWorker();
  BackgroundWorker(const BackgroundWorker&) = delete;
  BackgroundWorker& operator=(const BackgroundWorker&) = delete;

  /// Starts `job` unless one is running; returns whether it started.
  bool tryStart(std::function<void()> job);
  bool busy() const;
  /// Blocks until no job runs.
  void waitUntilIdle();
  /// False where the thread could not be created and jobs run on the offering thread.
  bool hasOwnThread() const { return thread_.joinable(); }

 private:
  void loop();
  void run(const std::function<void()>& job) noexcept;

  std::function<void(std::exception_ptr)> on_error_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::function<void()> job_;  // the job to run or running; empty when idle
  bool stopping_ = false;
  std::thread thread_;  // last: started once the state above exists
};

}  // namespace asr_ism
