#pragma once
// A bounded pool of geometry workers: a fixed number of threads and a bounded job queue, so heavy
// geometry never takes more cores than configured and a flood of requests is refused
// (RESOURCE_EXHAUSTED) rather than queued without bound.
//
// Each job carries its own stop condition (deadline and cancel flag); the pool passes it to the
// job as a CancelHook so long computations stop when the caller gives up. A job whose stop
// condition already holds when a worker picks it up still runs: it sees cancelled() at once and
// ends, so its owner always gets an answer.
//
// Priority: the daemon runs its work in lanes (pipeline.hpp): stroke analyses on normal-priority
// threads, geometry RPCs on lowered-priority threads and live previews on idle-priority threads,
// so heavy geometry never delays the reader threads or a stroke's shape.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace penshape::daemon {

// When a job should stop: a deadline, an external flag, or both.
class StopCondition {
 public:
  using Clock = std::chrono::steady_clock;
  StopCondition() = default;
  StopCondition(Clock::time_point deadline, std::function<bool()> cancelled)
      : deadline_(deadline), cancelled_(std::move(cancelled)) {}

  [[nodiscard]] bool deadline_passed() const { return Clock::now() >= deadline_; }
  [[nodiscard]] bool cancelled() const { return cancelled_ && cancelled_(); }
  [[nodiscard]] bool should_stop() const { return deadline_passed() || cancelled(); }
  [[nodiscard]] Clock::time_point deadline() const { return deadline_; }

 private:
  Clock::time_point deadline_ = Clock::time_point::max();
  std::function<bool()> cancelled_;
};

// How the pool's threads are scheduled (Linux; elsewhere every pool runs at normal priority).
enum class WorkerPriority {
  kNormal,      // as the daemon's other threads
  kInteractive, // nice + kInteractiveNice: work a user waits for (a stroke's shape)
  kBatch,       // nice + kBatchNice: long geometry calls; yield to everything above
  kIdle,        // SCHED_IDLE: runs only on otherwise idle cores (hints nobody waits for)
};
inline constexpr int kInteractiveNice = 5;
inline constexpr int kBatchNice = 15;

class WorkerPool {
 public:
  using Job = std::function<void(const StopCondition&)>;

  // threads == 0: one per hardware thread. max_queued: jobs waiting (not running) at most.
  // A priority the system refuses leaves the thread at normal priority (logged nowhere: raising
  // niceness and SCHED_IDLE need no privilege on Linux, so it does not happen in practice).
  WorkerPool(std::size_t threads, std::size_t max_queued,
             WorkerPriority priority = WorkerPriority::kNormal);
  ~WorkerPool(); // drain() then join
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // Queues a job; false when the queue is full or the pool is draining (the job is dropped).
  bool submit(Job job, StopCondition stop = {});
  // Refuses new jobs and returns once every accepted job has finished.
  void drain();

  [[nodiscard]] std::size_t thread_count() const { return threads_.size(); }
  [[nodiscard]] WorkerPriority priority() const { return priority_; }
  [[nodiscard]] std::size_t queued() const;
  [[nodiscard]] bool accepting() const;
  // Jobs queued or running.
  [[nodiscard]] std::size_t busy() const;

 private:
  struct Entry {
    Job job;
    StopCondition stop;
  };
  void run();
  void apply_priority() const;

  mutable std::mutex mutex_;
  std::condition_variable work_available_;
  std::condition_variable idle_;
  std::deque<Entry> queue_;
  std::size_t max_queued_;
  WorkerPriority priority_;
  std::size_t running_ = 0;
  bool accepting_ = true;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

} // namespace penshape::daemon
