#pragma once
// The shape hub fans live events out to subscribers through bounded per-subscriber queues.
//
// publish() never waits for a subscriber: it appends to each matching queue under that queue's own
// short lock; a full queue drops its *oldest* event and counts it. The subscriber learns the count
// with its next event (Delivery::dropped), so a slow reader loses old events, knows how many, and
// never stalls the producer or the other subscribers.
//
// Raw reports are the highest-rate events: a producer builds one only while wants_raw_reports()
// (some subscriber asked for them; a relaxed atomic load), so they cost nothing otherwise, and at
// most max_raw_subscribers subscriptions may ask for them at once.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <shared_mutex>
#include <string>
#include <vector>

#include "penshape/v1/live.pb.h"

namespace penshape::daemon {

using EventPtr = std::shared_ptr<const v1::LiveEvent>;

// Which events a subscriber wants.
struct EventFilter {
  bool devices = false; // device_attached / device_detached
  bool strokes = true;  // stroke_started / stroke_finished / shape
  bool samples = false;
  bool previews = false;
  // raw_report events, and with them device_attached / device_detached of the chosen devices, so
  // a capture sees in one ordered stream where each device's reports begin and end.
  bool raw_reports = false;
  bool deconstructions = false;     // stroke_deconstructed (computed only while someone asks)
  std::set<std::string> device_ids; // empty: every device
  [[nodiscard]] bool accepts(const v1::LiveEvent& event) const;
};

class ShapeHub;

// One subscriber's queue. Owned by the subscriber (e.g. a gRPC stream handler); unregisters itself
// from the hub when destroyed.
class Subscription {
 public:
  struct Delivery {
    EventPtr event;            // null when the wait timed out or the hub closed with nothing left
    std::uint64_t dropped = 0; // events lost just before this one (report them first)
    std::uint64_t dropped_total = 0;
    bool more = false; // more events were already queued behind this one
  };

  ~Subscription();
  Subscription(const Subscription&) = delete;
  Subscription& operator=(const Subscription&) = delete;

  // Waits up to `timeout` for the next event. After the hub closes, returns the events still queued
  // and then nulls with finished() true.
  Delivery next(std::chrono::milliseconds timeout);
  // The hub closed and this queue is empty: nothing will come any more.
  [[nodiscard]] bool finished() const;
  [[nodiscard]] std::uint64_t dropped_total() const;

 private:
  friend class ShapeHub;
  Subscription(ShapeHub& hub, EventFilter filter, std::size_t capacity);
  // Appends the event when the filter accepts it (true: the subscriber must be woken).
  bool enqueue(const EventPtr& event);
  void wake();
  void close();

  ShapeHub& hub_;
  const EventFilter filter_;
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<EventPtr> queue_;
  std::uint64_t dropped_pending_ = 0;
  std::uint64_t dropped_total_ = 0;
  bool closed_ = false;
};

class ShapeHub {
 public:
  // max_raw_subscribers: how many of them may take raw reports (EventFilter::raw_reports).
  explicit ShapeHub(std::size_t max_subscribers, std::size_t max_raw_subscribers = 8);
  ~ShapeHub();
  ShapeHub(const ShapeHub&) = delete;
  ShapeHub& operator=(const ShapeHub&) = delete;

  enum class Refusal { kNone, kFull, kRawFull, kClosed };
  // A new subscription with a queue of `capacity` events (>= 1); null when max_subscribers are
  // subscribed, when it wants raw reports and max_raw_subscribers already take them, or when the
  // hub is closed (`why` says which).
  std::unique_ptr<Subscription> subscribe(EventFilter filter, std::size_t capacity,
                                          Refusal* why = nullptr);

  // Stamps sequence and published_us, then fans the event out. Thread-safe; never blocks on a
  // subscriber. After close() events are discarded. Returns the event's sequence (0: discarded).
  std::uint64_t publish(v1::LiveEvent event);
  // Ends every subscription once its queue is drained; new subscriptions are refused.
  void close();

  // Some subscriber takes raw reports now. Lock-free: producers call it once per report.
  [[nodiscard]] bool wants_raw_reports() const {
    return raw_subscribers_.load(std::memory_order_relaxed) != 0;
  }

  [[nodiscard]] std::size_t subscriber_count() const;
  // Some subscriber asked for preview candidates (previews cost geometry: none without a reader).
  [[nodiscard]] bool wants_previews() const;
  // Some subscriber asked for stroke deconstructions (also computed only for a reader).
  [[nodiscard]] bool wants_deconstructions() const;
  [[nodiscard]] std::uint64_t published() const;

 private:
  friend class Subscription;
  void unsubscribe(Subscription* subscription);

  const std::size_t max_subscribers_;
  const std::size_t max_raw_subscribers_;
  std::atomic<std::size_t> raw_subscribers_{0}; // changed under mutex_ (exclusive)
  mutable std::shared_mutex mutex_; // guards subscribers_ and closed_; shared while publishing
  std::vector<Subscription*> subscribers_;
  bool closed_ = false;
  // Serialises publishers so each queue receives events in sequence order.
  std::mutex publish_mutex_;
  std::atomic<std::uint64_t> sequence_{0};
  std::atomic<std::size_t> preview_subscribers_{0};
  std::atomic<std::size_t> deconstruction_subscribers_{0};
};

// CLOCK_MONOTONIC in microseconds (LiveEvent.published_us).
std::int64_t monotonic_us();

} // namespace penshape::daemon
