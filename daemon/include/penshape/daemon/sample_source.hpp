#pragma once
// The boundary between the device side (drivers: device manager, one reader thread per device,
// stroke segmenter, recording replay) and the daemon. The drivers implement SampleSource; the
// daemon implements SampleSink and hands it to start().
//
// Threading: a source calls the sink from any of its threads (typically one per device); the sink
// never blocks for long (it queues work and returns), so a reader thread keeps up with the tablet.
// Per device, calls arrive in order: attached, then for each stroke started → samples → finished,
// then detached.
#include <cstdint>
#include <string>
#include <vector>

#include "penshape/types/pen_sample.hpp"
#include "penshape/types/stroke.hpp"
#include "penshape/types/tablet_info.hpp"

namespace penshape::daemon {

struct DeviceDescriptor {
  std::string id;     // stable while attached, unique among attached devices ("hidraw3")
  TabletInfo tablet;  // maxima and resolution of its samples
  std::string source; // device path or recording file name
  bool replay = false;
};

class SampleSink {
 public:
  virtual ~SampleSink() = default;
  virtual void device_attached(const DeviceDescriptor& device) = 0;
  virtual void device_detached(const std::string& device_id) = 0;
  // Tip down: a stroke begins. `stroke_id` is unique per source run (Stroke::id).
  virtual void stroke_started(const std::string& device_id, std::uint64_t stroke_id) = 0;
  // Every decoded sample; stroke_id is the current stroke's id, 0 while the pen hovers.
  virtual void sample(const std::string& device_id, std::uint64_t stroke_id,
                      const PenSample& sample) = 0;
  // Tip up: the whole stroke (also emitted for a stroke cut short by detach or stop()).
  virtual void stroke_finished(const std::string& device_id, Stroke stroke) = 0;
};

class SampleSource {
 public:
  virtual ~SampleSource() = default;
  // Starts delivering to `sink` (which outlives the source's use of it). Throws
  // std::runtime_error when the source cannot start (e.g. an unreadable recording).
  virtual void start(SampleSink& sink) = 0;
  // Stops reading and returns once no callback runs any more. A stroke in progress is finished
  // (stroke_finished is called for it) before stop() returns: shutdown loses no stroke.
  virtual void stop() = 0;
  // The devices attached now.
  [[nodiscard]] virtual std::vector<DeviceDescriptor> devices() const = 0;
};

} // namespace penshape::daemon
