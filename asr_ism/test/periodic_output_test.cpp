#include "asr_ism/periodic_output.hpp"

#include <gtest/gtest.h>

#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace asr_ism {
namespace {

struct Published {
  int result;
  bool fresh;
  bool operator==(const Published& other) const {
    return result == other.result && fresh == other.fresh;
  }
};

// Records what is published; computations are held until the test releases them, so the test
// decides which tick finds one running (no timing involved).
class Recorder {
 public:
  Recorder()
      : output_([this](const int& result, bool fresh) { record(result, fresh); },
                [this](std::exception_ptr) { ++errors_; }) {}

  // A tick whose computation (if it starts) returns `result` once released.
  std::shared_ptr<std::promise<void>> tickHeld(std::optional<int> result) {
    auto release = std::make_shared<std::promise<void>>();
    std::shared_future<void> released = release->get_future().share();
    output_.tick([released, result] {
      released.wait();
      return result;
    });
    return release;
  }
  // A tick whose computation (if it starts) returns at once.
  void tickNow(std::optional<int> result) { tickHeld(result)->set_value(); }
  void tickThrowing() {
    output_.tick([]() -> std::optional<int> { throw std::runtime_error("refused"); });
  }
  void waitUntilIdle() { output_.waitUntilIdle(); }

  std::vector<Published> published() {
    std::lock_guard<std::mutex> lock(mutex_);
    return published_;
  }
  int errors() const { return errors_; }

 private:
  void record(int result, bool fresh) {
    std::lock_guard<std::mutex> lock(mutex_);
    published_.push_back({result, fresh});
  }

  std::mutex mutex_;
  std::vector<Published> published_;
  int errors_ = 0;  // written on the worker's thread, read after waitUntilIdle
  PeriodicOutput<int> output_;
};

TEST(PeriodicOutput, PublishesEachResultAsSoonAsItIsComputed) {
  Recorder recorder;
  recorder.tickNow(1);
  recorder.waitUntilIdle();
  recorder.tickNow(2);
  recorder.waitUntilIdle();
  EXPECT_EQ(recorder.published(), (std::vector<Published>{{1, true}, {2, true}}));
}

TEST(PeriodicOutput, RepeatsTheLastResultWhileAComputationRuns) {
  Recorder recorder;
  recorder.tickNow(1);
  recorder.waitUntilIdle();
  const auto release = recorder.tickHeld(2);  // starts: the worker is idle
  recorder.tickNow(3);                        // busy: 1 again, 3 is not computed
  recorder.tickNow(4);                        // busy: 1 again
  release->set_value();
  recorder.waitUntilIdle();
  recorder.tickNow(5);
  recorder.waitUntilIdle();
  EXPECT_EQ(recorder.published(),
            (std::vector<Published>{{1, true}, {1, false}, {1, false}, {2, true}, {5, true}}));
}

TEST(PeriodicOutput, NothingIsRepeatedBeforeTheFirstResult) {
  Recorder recorder;
  const auto release = recorder.tickHeld(1);
  recorder.tickNow(2);
  recorder.tickNow(3);
  EXPECT_TRUE(recorder.published().empty());
  release->set_value();
  recorder.waitUntilIdle();
  EXPECT_EQ(recorder.published(), (std::vector<Published>{{1, true}}));
}

TEST(PeriodicOutput, ARefusalOrAnErrorLeavesNothingToRepeat) {
  Recorder recorder;
  recorder.tickNow(1);
  recorder.waitUntilIdle();
  auto release = recorder.tickHeld(std::nullopt);  // refused
  release->set_value();
  recorder.waitUntilIdle();
  release = recorder.tickHeld(2);
  recorder.tickNow(3);  // busy, and there is no last result to repeat
  release->set_value();
  recorder.waitUntilIdle();
  recorder.tickThrowing();
  recorder.waitUntilIdle();
  release = recorder.tickHeld(4);
  recorder.tickNow(5);  // busy, nothing to repeat after the error
  release->set_value();
  recorder.waitUntilIdle();
  EXPECT_EQ(recorder.published(), (std::vector<Published>{{1, true}, {2, true}, {4, true}}));
  EXPECT_EQ(recorder.errors(), 1);
}

}  // namespace
}  // namespace asr_ism
