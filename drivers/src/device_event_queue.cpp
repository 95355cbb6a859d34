#include "penshape/drivers/device_event_queue.hpp"

#include <algorithm>

namespace penshape::drivers {

void DeviceEventQueue::push(DeviceEvent&& e) {
  {
    std::lock_guard lock(mutex_);
    if (e.kind == DeviceEvent::Kind::kSample) {
      if (samples_waiting_ >= max_samples_) {
        // Drop the oldest waiting sample; strokes still carry every sample they hold.
        const auto it = std::find_if(events_.begin(), events_.end(), [](const DeviceEvent& x) {
          return x.kind == DeviceEvent::Kind::kSample;
        });
        if (it != events_.end()) {
          events_.erase(it);
          --samples_waiting_;
          ++dropped_;
        }
      }
      ++samples_waiting_;
    }
    events_.push_back(std::move(e));
  }
  ready_.notify_one();
}

DeviceCallbacks DeviceEventQueue::callbacks() {
  return {
      .on_attach =
          [this](const AttachedDevice& d) {
            DeviceEvent e;
            e.kind = DeviceEvent::Kind::kAttach;
            e.device = d.id;
            e.attached = d;
            push(std::move(e));
          },
      .on_detach =
          [this](DeviceId id, DetachReason why, const PipelineCounters& c) {
            DeviceEvent e;
            e.kind = DeviceEvent::Kind::kDetach;
            e.device = id;
            e.reason = why;
            e.counters = c;
            push(std::move(e));
          },
      .on_sample =
          [this](DeviceId id, const PenSample& s) {
            DeviceEvent e;
            e.kind = DeviceEvent::Kind::kSample;
            e.device = id;
            e.sample = s;
            push(std::move(e));
          },
      .on_stroke =
          [this](DeviceId id, Stroke&& s) {
            DeviceEvent e;
            e.kind = DeviceEvent::Kind::kStroke;
            e.device = id;
            e.stroke = std::move(s);
            push(std::move(e));
          },
  };
}

std::optional<DeviceEvent> DeviceEventQueue::pop(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  if (!ready_.wait_for(lock, timeout, [&] { return !events_.empty(); })) return std::nullopt;
  DeviceEvent e = std::move(events_.front());
  events_.pop_front();
  if (e.kind == DeviceEvent::Kind::kSample) --samples_waiting_;
  return e;
}

std::size_t DeviceEventQueue::dropped_samples() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

std::size_t DeviceEventQueue::size() const {
  std::lock_guard lock(mutex_);
  return events_.size();
}

} // namespace penshape::drivers
