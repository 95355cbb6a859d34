#include "penshape/daemon/worker_pool.hpp"

#include <algorithm>

#include "thread_scheduling.hpp"

namespace penshape::daemon {

WorkerPool::WorkerPool(std::size_t threads, std::size_t max_queued, WorkerPriority priority)
    : max_queued_(std::max<std::size_t>(max_queued, 1)), priority_(priority) {
  if (threads == 0) threads = std::max(1U, std::thread::hardware_concurrency());
  threads_.reserve(threads);
  for (std::size_t i = 0; i < threads; ++i) {
    threads_.emplace_back([this] {
      apply_priority();
      run();
    });
  }
}

// Called on the worker thread itself: Linux keeps niceness and policy per thread.
void WorkerPool::apply_priority() const {
  switch (priority_) {
    case WorkerPriority::kNormal:
      break;
    case WorkerPriority::kInteractive:
      lower_current_thread(kInteractiveNice);
      break;
    case WorkerPriority::kBatch:
      lower_current_thread(kBatchNice);
      break;
    case WorkerPriority::kIdle:
      make_current_thread_idle();
      break;
  }
}

WorkerPool::~WorkerPool() {
  drain();
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  work_available_.notify_all();
  for (auto& t : threads_) t.join();
}

bool WorkerPool::submit(Job job, StopCondition stop) {
  {
    std::lock_guard lock(mutex_);
    if (!accepting_ || queue_.size() >= max_queued_) return false;
    queue_.push_back({std::move(job), std::move(stop)});
  }
  work_available_.notify_one();
  return true;
}

void WorkerPool::drain() {
  std::unique_lock lock(mutex_);
  accepting_ = false;
  idle_.wait(lock, [this] { return queue_.empty() && running_ == 0; });
}

std::size_t WorkerPool::queued() const {
  std::lock_guard lock(mutex_);
  return queue_.size();
}

std::size_t WorkerPool::busy() const {
  std::lock_guard lock(mutex_);
  return queue_.size() + running_;
}

bool WorkerPool::accepting() const {
  std::lock_guard lock(mutex_);
  return accepting_;
}

void WorkerPool::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    work_available_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return; // stopping, nothing left
    Entry entry = std::move(queue_.front());
    queue_.pop_front();
    ++running_;
    lock.unlock();
    // A job reports its own failures to its owner; one that throws anyway must not take the
    // worker down with it.
    try {
      entry.job(entry.stop);
    } catch (...) {
    }
    entry = {};
    lock.lock();
    --running_;
    if (queue_.empty() && running_ == 0) idle_.notify_all();
  }
}

} // namespace penshape::daemon
