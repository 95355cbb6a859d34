#include "penshape/daemon/shape_hub.hpp"

#include <time.h>

#include <algorithm>

namespace penshape::daemon {

std::int64_t monotonic_us() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

namespace {

// Whether the filter asks for events of this kind (from any device).
bool wants_kind(const EventFilter& f, v1::LiveEvent::KindCase kind) {
  switch (kind) {
    case v1::LiveEvent::kDeviceAttached:
    case v1::LiveEvent::kDeviceDetached:
      return f.devices || f.raw_reports;
    case v1::LiveEvent::kRawReport:
      return f.raw_reports;
    case v1::LiveEvent::kSamples:
      return f.samples;
    case v1::LiveEvent::kPreview:
      return f.previews;
    case v1::LiveEvent::kDeconstructed:
      return f.deconstructions;
    case v1::LiveEvent::kStrokeStarted:
    case v1::LiveEvent::kStrokeFinished:
    case v1::LiveEvent::kShape:
      return f.strokes;
    default:
      return false;
  }
}

} // namespace

bool EventFilter::accepts(const v1::LiveEvent& event) const {
  return wants_kind(*this, event.kind_case()) &&
         (device_ids.empty() || device_ids.count(event.device_id()) != 0);
}

Subscription::Subscription(ShapeHub& hub, EventFilter filter, std::size_t capacity)
    : hub_(hub), filter_(std::move(filter)), capacity_(std::max<std::size_t>(capacity, 1)) {}

Subscription::~Subscription() { hub_.unsubscribe(this); }

bool Subscription::enqueue(const EventPtr& event) {
  if (!filter_.accepts(*event)) return false;
  std::lock_guard lock(mutex_);
  if (closed_) return false;
  if (queue_.size() >= capacity_) {
    queue_.pop_front();
    ++dropped_pending_;
    ++dropped_total_;
  }
  queue_.push_back(event);
  return true;
}

void Subscription::wake() { ready_.notify_one(); }

void Subscription::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  ready_.notify_all();
}

Subscription::Delivery Subscription::next(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  ready_.wait_for(lock, timeout, [this] { return !queue_.empty() || closed_; });
  Delivery delivery;
  if (queue_.empty()) return delivery;
  delivery.event = std::move(queue_.front());
  queue_.pop_front();
  delivery.dropped = dropped_pending_;
  delivery.dropped_total = dropped_total_;
  delivery.more = !queue_.empty();
  dropped_pending_ = 0;
  return delivery;
}

bool Subscription::finished() const {
  std::lock_guard lock(mutex_);
  return closed_ && queue_.empty();
}

std::uint64_t Subscription::dropped_total() const {
  std::lock_guard lock(mutex_);
  return dropped_total_;
}

ShapeHub::ShapeHub(std::size_t max_subscribers, std::size_t max_raw_subscribers)
    : max_subscribers_(max_subscribers), max_raw_subscribers_(max_raw_subscribers) {}

ShapeHub::~ShapeHub() { close(); }

std::unique_ptr<Subscription> ShapeHub::subscribe(EventFilter filter, std::size_t capacity,
                                                  Refusal* why) {
  std::unique_lock lock(mutex_);
  Refusal refusal = Refusal::kNone;
  if (closed_) {
    refusal = Refusal::kClosed;
  } else if (subscribers_.size() >= max_subscribers_) {
    refusal = Refusal::kFull;
  } else if (filter.raw_reports && raw_subscribers_.load() >= max_raw_subscribers_) {
    refusal = Refusal::kRawFull;
  }
  if (why != nullptr) *why = refusal;
  if (refusal != Refusal::kNone) return nullptr;
  const bool raw = filter.raw_reports;
  std::unique_ptr<Subscription> subscription(new Subscription(*this, std::move(filter), capacity));
  subscribers_.push_back(subscription.get());
  if (subscription->filter_.previews) preview_subscribers_.fetch_add(1);
  if (subscription->filter_.deconstructions) deconstruction_subscribers_.fetch_add(1);
  if (raw) raw_subscribers_.fetch_add(1);
  return subscription;
}

void ShapeHub::unsubscribe(Subscription* subscription) {
  std::unique_lock lock(mutex_);
  const auto it = std::remove(subscribers_.begin(), subscribers_.end(), subscription);
  if (it == subscribers_.end()) return;
  subscribers_.erase(it, subscribers_.end());
  if (subscription->filter_.previews) preview_subscribers_.fetch_sub(1);
  if (subscription->filter_.deconstructions) deconstruction_subscribers_.fetch_sub(1);
  if (subscription->filter_.raw_reports) raw_subscribers_.fetch_sub(1);
}

// Publishers run at every priority: tablet readers (normal), stroke analyses (nice 5), previews
// (SCHED_IDLE). A low-priority publisher must never hold publish_mutex_ for long, or a reader
// waits behind it (priority inversion): so the event is allocated before the lock, the critical
// section only numbers it and appends it to the queues, and the subscribers are woken after it
// is released (a woken subscriber thread preempts a low-priority waker at once; it must not do so
// while the waker holds the lock every reader needs).
std::uint64_t ShapeHub::publish(v1::LiveEvent event) {
  const auto shared = std::make_shared<v1::LiveEvent>(std::move(event));
  thread_local std::vector<Subscription*> woken;
  woken.clear();
  std::shared_lock lock(mutex_); // shared: publishers never wait for each other here
  if (closed_) return 0;
  std::uint64_t sequence = 0;
  {
    std::lock_guard order(publish_mutex_);
    sequence = sequence_.fetch_add(1) + 1;
    shared->set_sequence(sequence);
    shared->set_published_us(monotonic_us());
    const EventPtr event_ptr = shared;
    for (Subscription* s : subscribers_) {
      if (s->enqueue(event_ptr)) woken.push_back(s);
    }
  }
  for (Subscription* s : woken) s->wake(); // still registered: the shared lock is held
  return sequence;
}

void ShapeHub::close() {
  std::unique_lock lock(mutex_);
  closed_ = true;
  for (Subscription* s : subscribers_) s->close();
}

std::size_t ShapeHub::subscriber_count() const {
  std::shared_lock lock(mutex_);
  return subscribers_.size();
}

bool ShapeHub::wants_previews() const { return preview_subscribers_.load() > 0; }

bool ShapeHub::wants_deconstructions() const { return deconstruction_subscribers_.load() > 0; }

std::uint64_t ShapeHub::published() const { return sequence_.load(); }

} // namespace penshape::daemon
