#pragma once
// A queue adapter for the device manager's callbacks: the daemon hands `callbacks()` to the
// DeviceManager and pops events on its own thread. Attach, stroke and detach events are never
// dropped; pen samples are (oldest first) when more than `max_samples` wait, and counted, so a
// stalled consumer cannot grow memory without bound.
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <optional>

#include "penshape/drivers/device_manager.hpp"

namespace penshape::drivers {

struct DeviceEvent {
  enum class Kind : std::uint8_t { kAttach, kSample, kStroke, kDetach };
  Kind kind = Kind::kSample;
  DeviceId device = 0;
  AttachedDevice attached;                   // kAttach
  PenSample sample;                          // kSample
  Stroke stroke;                             // kStroke
  DetachReason reason = DetachReason::kGone; // kDetach
  PipelineCounters counters;                 // kDetach
};

class DeviceEventQueue {
 public:
  explicit DeviceEventQueue(std::size_t max_samples = 65536) : max_samples_(max_samples) {}

  // Callbacks that push into this queue (the queue must outlive the manager using them).
  DeviceCallbacks callbacks();

  // The next event, waiting up to `timeout`; nullopt on timeout.
  std::optional<DeviceEvent> pop(std::chrono::milliseconds timeout);

  [[nodiscard]] std::size_t dropped_samples() const;
  [[nodiscard]] std::size_t size() const;

 private:
  void push(DeviceEvent&& e);

  std::size_t max_samples_;
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<DeviceEvent> events_;
  std::size_t samples_waiting_ = 0;
  std::size_t dropped_ = 0;
};

} // namespace penshape::drivers
