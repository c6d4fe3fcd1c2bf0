#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace asr_ism {

/// The one pool of worker threads the suite's parallel loops share. `parallelFor` hands out
/// indices dynamically; callers write results per index, so results do not depend on the number
/// of threads. A parallelFor issued from inside another runs serially on the calling thread.
class ThreadPool {
 public:
  /// `threads` counts the calling thread too; 0 means one per hardware thread.
  explicit ThreadPool(unsigned threads = 0);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  unsigned threadCount() const { return static_cast<unsigned>(workers_.size()) + 1; }

  /// Calls task(index) for every index in [0, count), on any of the pool's threads; tasks that
  /// need scratch space keep it thread_local.
  void parallelFor(std::size_t count, const std::function<void(std::size_t)>& task);

 private:
  // One parallelFor call. A worker that wakes late holds its own job, so it can never run
  // indices of a later call with a finished call's task.
  struct Job {
    const std::function<void(std::size_t)>* task = nullptr;
    std::size_t count = 0;
    std::atomic<std::size_t> next{0};
    unsigned active_workers = 0;  // guarded by mutex_
  };

  void workerLoop();
  static void runIndices(Job& job);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  std::shared_ptr<Job> job_;  // guarded by mutex_
  std::size_t generation_ = 0;
  bool stopping_ = false;
  std::mutex submit_mutex_;
};

}  // namespace asr_ism
