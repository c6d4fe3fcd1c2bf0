#include "asr_ism/background_worker.hpp"

#include <utility>

namespace asr_ism {

BackgroundWorker::BackgroundWorker(std::function<void(std::exception_ptr)> on_error)
    : on_error_(std::move(on_error)) {
  try {
    thread_ = std::thread([this] { loop(); });
  } catch (const std::exception&) {
    // std::system_error (no resources for a thread): tryStart runs jobs on the caller's thread.
  }
}

BackgroundWorker::~BackgroundWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable())
    thread_.join();
}

bool BackgroundWorker::tryStart(std::function<void()> job) {
  if (!job)
    return false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (job_ || stopping_)
      return false;
    job_ = std::move(job);
  }
  if (!thread_.joinable()) {
    run(job_);
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = nullptr;
    return true;
  }
  changed_.notify_all();
  return true;
}

bool BackgroundWorker::busy() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<bool>(job_);
}

void BackgroundWorker::waitUntilIdle() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return !job_; });
}

void BackgroundWorker::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    // A job offered before stopping still runs: its caller was told it started.
    changed_.wait(lock, [&] { return stopping_ || job_; });
    if (!job_)
      return;
    lock.unlock();
    run(job_);  // job_ is not replaced while set
    lock.lock();
    job_ = nullptr;
    changed_.notify_all();
  }
}

void BackgroundWorker::run(const std::function<void()>& job) noexcept {
  try {
    job();
  } catch (...) {
    if (on_error_) {
      try {
        on_error_(std::current_exception());
      } catch (...) {
        // An error handler that throws must not end the process either.
      }
    }
  }
}

}  // namespace asr_ism
