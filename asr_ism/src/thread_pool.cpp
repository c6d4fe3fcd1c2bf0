#include "asr_ism/thread_pool.hpp"

#include <algorithm>

namespace asr_ism {
namespace {
thread_local bool inside_parallel_for = false;
}  // namespace

ThreadPool::ThreadPool(unsigned threads) {
  if (threads == 0) {
    threads = std::max(1u, std::thread::hardware_concurrency());
  }
  for (unsigned worker = 1; worker < threads; ++worker) {
    workers_.emplace_back([this] { workerLoop(); });
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

void ThreadPool::runIndices(Job& job) {
  for (std::size_t index = job.next.fetch_add(1); index < job.count;
       index = job.next.fetch_add(1)) {
    (*job.task)(index);
  }
}

void ThreadPool::workerLoop() {
  std::size_t seen_generation = 0;
  inside_parallel_for = true;
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
  std::unique_lock<std::mutex> submit_lock(submit_mutex_, std::defer_lock);
  // Serial when nested, when there is nothing to share, or when another thread owns the pool.
  if (inside_parallel_for || workers_.empty() || count == 1 || !submit_lock.try_lock()) {
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
  inside_parallel_for = true;
  runIndices(*job);
  inside_parallel_for = false;
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [&] { return job->active_workers == 0; });
  job_.reset();
}

}  // namespace asr_ism
