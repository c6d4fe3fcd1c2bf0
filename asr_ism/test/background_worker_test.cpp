#include "asr_ism/background_worker.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <future>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace asr_ism {
namespace {

// A job that runs until released, so a test decides when it ends (no timing involved).
struct HeldJob {
  std::promise<void> started;
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();

  std::function<void()> job() {
    return [this] {
      started.set_value();
      released.wait();
    };
  }
};

std::function<void(std::exception_ptr)> ignoreErrors() {
  return [](std::exception_ptr) {};
}

TEST(BackgroundWorker, RunsAJobOnAnotherThread) {
  BackgroundWorker worker(ignoreErrors());
  ASSERT_TRUE(worker.hasOwnThread());
  std::promise<std::thread::id> ran_on;
  ASSERT_TRUE(worker.tryStart([&] { ran_on.set_value(std::this_thread::get_id()); }));
  EXPECT_NE(ran_on.get_future().get(), std::this_thread::get_id());
  worker.waitUntilIdle();
  EXPECT_FALSE(worker.busy());
}

TEST(BackgroundWorker, RefusesAJobWhileOneRunsAndTakesOneAfterwards) {
  BackgroundWorker worker(ignoreErrors());
  HeldJob held;
  ASSERT_TRUE(worker.tryStart(held.job()));
  held.started.get_future().wait();
  bool refused_ran = false;
  EXPECT_FALSE(worker.tryStart([&] { refused_ran = true; }));
  EXPECT_TRUE(worker.busy());
  held.release.set_value();
  worker.waitUntilIdle();
  EXPECT_FALSE(refused_ran);
  std::atomic<bool> next_ran{false};
  ASSERT_TRUE(worker.tryStart([&] { next_ran = true; }));
  worker.waitUntilIdle();
  EXPECT_TRUE(next_ran);
}

TEST(BackgroundWorker, AJobsExceptionGoesToTheHandlerAndTheWorkerGoesOn) {
  std::vector<std::string> errors;
  BackgroundWorker worker([&](std::exception_ptr error) {
    try {
      std::rethrow_exception(error);
    } catch (const std::exception& caught) {
      errors.push_back(caught.what());
    }
  });
  ASSERT_TRUE(worker.tryStart([] { throw std::runtime_error("first"); }));
  worker.waitUntilIdle();
  ASSERT_TRUE(worker.tryStart([] { throw 42; }));  // not a std::exception
  worker.waitUntilIdle();
  bool ran = false;
  ASSERT_TRUE(worker.tryStart([&] { ran = true; }));
  worker.waitUntilIdle();
  EXPECT_EQ(errors, std::vector<std::string>{"first"});
  EXPECT_TRUE(ran);
}

TEST(BackgroundWorker, AThrowingHandlerDoesNotEndTheProcess) {
  BackgroundWorker worker([](std::exception_ptr) { throw std::logic_error("handler"); });
  ASSERT_TRUE(worker.tryStart([] { throw std::runtime_error("job"); }));
  worker.waitUntilIdle();
  bool ran = false;
  ASSERT_TRUE(worker.tryStart([&] { ran = true; }));
  worker.waitUntilIdle();
  EXPECT_TRUE(ran);
}

TEST(BackgroundWorker, DestructionWaitsForTheRunningJob) {
  HeldJob held;
  std::atomic<bool> finished{false};
  std::thread releaser;
  {
    BackgroundWorker worker(ignoreErrors());
    ASSERT_TRUE(worker.tryStart([&] {
      held.job()();
      finished = true;
    }));
    held.started.get_future().wait();
    releaser = std::thread([&] { held.release.set_value(); });
  }
  EXPECT_TRUE(finished);
  releaser.join();
}

TEST(BackgroundWorker, AnEmptyJobIsRefused) {
  BackgroundWorker worker(ignoreErrors());
  EXPECT_FALSE(worker.tryStart(nullptr));
  EXPECT_FALSE(worker.busy());
}

}  // namespace
}  // namespace asr_ism
