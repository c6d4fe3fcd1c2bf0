#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace asr_ism {

/// The one pool of worker threads the suite's parallel loops share. `parallelFor` hands out
/// indices dynamically; callers write results per index, so results do not depend on the number
/// of threads. A parallelFor issued while the pool is busy (from inside one of its tasks, or from
/// another thread at the same time) runs serially on the calling thread. All state is the pool's
/// own: pools do not affect each other, and a failed call leaves nothing behind.
class ThreadPool {
 public:
  /// `threads` counts the calling thread too; 0 means one per hardware thread. If the system
  /// cannot create as many threads (a memory or process limit), the pool keeps those it could
  /// create: threadCount() says how many that is.
  explicit ThreadPool(unsigned threads = 0);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  unsigned threadCount() const { return static_cast<unsigned>(workers_.size()) + 1; }

  /// Calls task(index) for every index in [0, count), on any of the pool's threads; tasks that
  /// need scratch space keep it thread_local. If a task throws, no further index is started, the
  /// call waits for the tasks running, and rethrows the first exception to the caller.
  void parallelFor(std::size_t count, const std::function<void(std::size_t)>& task);

 private:
  // One parallelFor call. A worker that wakes late holds its own job, so it can never run
  // indices of a later call with a finished call's task.
  struct Job {
    const std::function<void(std::size_t)>* task = nullptr;
    std::size_t count = 0;
    std::atomic<std::size_t> next{0};
    unsigned active_workers = 0;  // guarded by mutex_
    std::exception_ptr error;     // the first task exception, guarded by error_mutex
    std::mutex error_mutex;
  };

  void workerLoop();
  static void runIndices(Job& job) noexcept;

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  std::shared_ptr<Job> job_;  // guarded by mutex_
  std::size_t generation_ = 0;
  bool stopping_ = false;
  std::atomic<bool> busy_{false};  // a parallelFor is using the workers
};

}  // namespace asr_ism
