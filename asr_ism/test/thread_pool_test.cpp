#include "asr_ism/thread_pool.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <functional>
#include <stdexcept>
#include <thread>
#include <vector>

namespace asr_ism {
namespace {

// Counts how often each index is visited.
std::vector<int> visitCounts(ThreadPool& pool, std::size_t count) {
  std::vector<std::atomic<int>> visits(count);
  pool.parallelFor(count, [&](std::size_t index) { visits[index].fetch_add(1); });
  std::vector<int> result(count);
  for (std::size_t i = 0; i < count; ++i)
    result[i] = visits[i].load();
  return result;
}

// True if, in a parallelFor on `pool`, some task runs on another thread than the caller: the
// caller's tasks wait (up to 60 s) until one has.
bool workersTakePart(ThreadPool& pool) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> worker_ran{false};
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  pool.parallelFor(64, [&](std::size_t) {
    if (std::this_thread::get_id() != caller) {
      worker_ran = true;
      return;
    }
    while (!worker_ran && std::chrono::steady_clock::now() < give_up)
      std::this_thread::yield();
  });
  return worker_ran;
}

TEST(ThreadPool, CountsTheCallingThread) {
  EXPECT_EQ(ThreadPool(1).threadCount(), 1u);
  EXPECT_EQ(ThreadPool(3).threadCount(), 3u);
  EXPECT_GE(ThreadPool(0).threadCount(), 1u);
}

TEST(ThreadPool, VisitsEveryIndexExactlyOnce) {
  for (unsigned threads : {1u, 2u, 4u, 0u}) {
    ThreadPool pool(threads);
    for (std::size_t count : {0u, 1u, 2u, 7u, 1000u, 20000u}) {
      const std::vector<int> visits = visitCounts(pool, count);
      EXPECT_EQ(visits, std::vector<int>(count, 1)) << threads << " threads, " << count;
    }
  }
}

TEST(ThreadPool, ManyConsecutiveCallsEachVisitEveryIndexOnce) {
  // Back-to-back jobs: a worker waking late must not run a finished job's indices again.
  ThreadPool pool(4);
  for (int call = 0; call < 500; ++call) {
    const std::size_t count = 1 + call % 13;
    ASSERT_EQ(visitCounts(pool, count), std::vector<int>(count, 1)) << "call " << call;
  }
}

TEST(ThreadPool, NestedParallelForRunsSeriallyWithoutDeadlock) {
  ThreadPool pool(4);
  constexpr std::size_t kOuter = 16;
  constexpr std::size_t kInner = 50;
  std::vector<std::atomic<int>> visits(kOuter * kInner);
  std::atomic<int> inner_on_other_thread{0};
  pool.parallelFor(kOuter, [&](std::size_t outer) {
    const std::thread::id outer_thread = std::this_thread::get_id();
    pool.parallelFor(kInner, [&](std::size_t inner) {
      if (std::this_thread::get_id() != outer_thread)
        inner_on_other_thread.fetch_add(1);
      visits[outer * kInner + inner].fetch_add(1);
    });
  });
  for (std::size_t i = 0; i < visits.size(); ++i)
    ASSERT_EQ(visits[i].load(), 1) << i;
  EXPECT_EQ(inner_on_other_thread.load(), 0);
}

TEST(ThreadPool, CallsFromTwoThreadsAtOnceBothComplete) {
  // One caller gets the pool, the other runs serially; neither may lose or repeat an index.
  ThreadPool pool(3);
  std::vector<int> first, second;
  std::thread a([&] { first = visitCounts(pool, 5000); });
  std::thread b([&] { second = visitCounts(pool, 5000); });
  a.join();
  b.join();
  EXPECT_EQ(first, std::vector<int>(5000, 1));
  EXPECT_EQ(second, std::vector<int>(5000, 1));
}

TEST(ThreadPool, ResultsPerIndexDoNotDependOnTheThreadCount) {
  const auto compute = [](ThreadPool& pool) {
    std::vector<double> values(3000);
    pool.parallelFor(values.size(), [&](std::size_t index) {
      double value = 0.0;
      for (std::size_t k = 1; k <= 200; ++k)
        value += std::sin(static_cast<double>(index * k)) / static_cast<double>(k);
      values[index] = value;
    });
    return values;
  };
  ThreadPool serial(1);
  ThreadPool parallel(4);
  const std::vector<double> expected = compute(serial);
  EXPECT_EQ(compute(parallel), expected);
  EXPECT_EQ(compute(parallel), expected);
}

TEST(ThreadPool, ATaskExceptionReachesTheCallerAndThePoolStaysUsable) {
  // Property over seeds: whichever index throws, on whichever thread, the caller gets that
  // exception (never std::terminate), no index runs twice, and the next call is complete.
  for (unsigned threads : {1u, 2u, 4u}) {
    ThreadPool pool(threads);
    for (std::size_t failing = 0; failing < 200; failing += 7) {
      std::vector<std::atomic<int>> visits(200);
      try {
        pool.parallelFor(200, [&](std::size_t index) {
          visits[index].fetch_add(1);
          if (index == failing)
            throw std::runtime_error("task " + std::to_string(index));
        });
        ADD_FAILURE() << "no exception for index " << failing;
      } catch (const std::runtime_error& error) {
        EXPECT_EQ(std::string(error.what()), "task " + std::to_string(failing));
      }
      for (std::size_t i = 0; i < visits.size(); ++i)
        ASSERT_LE(visits[i].load(), 1) << i;
      EXPECT_EQ(visits[failing].load(), 1);
      ASSERT_EQ(visitCounts(pool, 1000), std::vector<int>(1000, 1)) << threads << " threads";
    }
  }
}

TEST(ThreadPool, AnExceptionOnAWorkerThreadReachesTheCaller) {
  // The caller's tasks wait until a worker has taken one, and the workers' tasks throw: the
  // exception crosses threads (before, it ended the process with std::terminate).
  ThreadPool pool(3);
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> worker_started{false};
  EXPECT_THROW(pool.parallelFor(1000,
                                [&](std::size_t) {
                                  if (std::this_thread::get_id() != caller) {
                                    worker_started = true;
                                    throw std::out_of_range("on a worker");
                                  }
                                  while (!worker_started)
                                    std::this_thread::yield();
                                }),
               std::out_of_range);
  EXPECT_EQ(visitCounts(pool, 1000), std::vector<int>(1000, 1));
}

TEST(ThreadPool, WhenEveryTaskThrowsOneExceptionArrives) {
  ThreadPool pool(4);
  EXPECT_THROW(pool.parallelFor(10000, [](std::size_t) { throw std::logic_error("every"); }),
               std::logic_error);
  // The failed call left no flag behind: the next call still uses the other threads (the
  // caller's tasks wait for a worker to take one; the bound only ends a broken pool's wait).
  EXPECT_TRUE(workersTakePart(pool));
}

TEST(ThreadPool, PoolsDoNotShareState) {
  // A loop of one pool inside a task of another is parallel in the inner pool: no process-wide
  // "inside a loop" flag makes it serial.
  ThreadPool outer(2);
  ThreadPool inner(3);
  std::atomic<int> parallel_inside{0};
  outer.parallelFor(2, [&](std::size_t index) {
    if (index == 0)
      parallel_inside += workersTakePart(inner);
  });
  EXPECT_GT(parallel_inside.load(), 0);
}

// Runs `body` in a child process under an address-space limit; returns its exit status, or -1
// if it had not ended after `seconds` (a hang; the limit only bounds a broken build).
int exitStatusUnderMemoryLimit(rlim_t bytes, int seconds, const std::function<int()>& body) {
  const pid_t child = fork();
  if (child == 0) {
    const rlimit limit{bytes, bytes};
    setrlimit(RLIMIT_AS, &limit);
    _exit(body());
  }
  int status = 0;
  for (int waited = 0; waited < seconds * 20; ++waited) {
    if (waitpid(child, &status, WNOHANG) == child)
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  kill(child, SIGKILL);
  waitpid(child, &status, 0);
  return -1;
}

TEST(ThreadPool, ThreadsThatCannotBeCreatedAreDoneWithout) {
  // 100000 threads do not fit in 1 GiB of address space (each reserves a stack): the pool keeps
  // those it could create and still completes every index; no hang, no abort.
  const int status = exitStatusUnderMemoryLimit(rlim_t{1} << 30, 120, [] {
    ThreadPool pool(100000);
    if (pool.threadCount() >= 100000u)
      return 3;  // the limit did not bite: the test would prove nothing
    std::vector<std::atomic<int>> visits(5000);
    pool.parallelFor(visits.size(), [&](std::size_t index) { visits[index].fetch_add(1); });
    for (const auto& visit : visits)
      if (visit.load() != 1)
        return 4;
    return 0;
  });
  EXPECT_EQ(status, 0) << "-1: hang; 3: no thread creation failed; 4: an index was lost; "
                          ">128: killed by a signal";
}

}  // namespace
}  // namespace asr_ism
