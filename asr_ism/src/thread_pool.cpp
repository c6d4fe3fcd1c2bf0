#include "asr_ism/thread_pool.hpp"

#include <algorithm>

namespace asr_ism {

ThreadPool::ThreadPool(unsigned threads) {
  if (threads == 0) {
    threads = std::max(1u, std::thread::hardware_concurrency());
  }
  workers_.reserve(threads - 1);
  for (unsigned worker = 1; worker < threads; ++worker) {
    try {
      workers_.emplace_back([this] { workerLoop(); });
    } catch (const std::exception&) {
      // std::system_error (no resources for a thread) or std::bad_alloc: work with the threads
      // there are; the calling thread alone still completes every call.
      break;
    }
  }
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& worker : workers_) {
    worker.join();
  }
}

void ThreadPool::runIndices(Job& job) noexcept {
  for (std::size_t index = job.next.fetch_add(1); index < job.count;
       index = job.next.fetch_add(1)) {
    try {
      (*job.task)(index);
    } catch (...) {
      std::lock_guard<std::mutex> lock(job.error_mutex);
      if (!job.error)
        job.error = std::current_exception();
      job.next.store(job.count);  // start no further index
    }
  }
}

void ThreadPool::workerLoop() {
  std::size_t seen_generation = 0;
  while (true) {
    std::shared_ptr<Job> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || (job_ && generation_ != seen_generation); });
      if (stopping_) {
        return;
      }
      seen_generation = generation_;
      job = job_;
      ++job->active_workers;
    }
    runIndices(*job);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      --job->active_workers;
    }
    done_.notify_all();
  }
}

void ThreadPool::parallelFor(std::size_t count, const std::function<void(std::size_t)>& task) {
  if (count == 0) {
    return;
  }
  // Serial when there is nothing to share, or when the pool is busy: nested in one of its own
  // tasks (on a worker or on the caller) or used by another thread.
  if (workers_.empty() || count == 1 || busy_.exchange(true)) {
    for (std::size_t index = 0; index < count; ++index) {
      task(index);
    }
    return;
  }
  auto job = std::make_shared<Job>();
  job->task = &task;
  job->count = count;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = job;
    ++generation_;
  }
  wake_.notify_all();
  runIndices(*job);
  {
    // The workers may still run tasks that refer to `task`: wait for them before returning.
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return job->active_workers == 0; });
    job_.reset();
  }
  busy_.store(false);
  if (job->error) {
    std::rethrow_exception(job->error);
  }
}

}  // namespace asr_ism
