#include "asr_ism/thread_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
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

}  // namespace
}  // namespace asr_ism
