#pragma once
// The boundary between the device side (drivers: device manager, one reader thread per device,
// stroke segmenter, recording replay) and the daemon. The drivers implement SampleSource; the
// daemon implements SampleSink and hands it to start().
//
// Threading: a source calls the sink from any of its threads (typically one per device); the sink
// never blocks for long (it queues work and returns), so a reader thread keeps up with the tablet.
// Per device, calls arrive in order: attached, then for each stroke started → samples → finished,
// then detached. Raw reports, when the sink wants them, come between attached and detached.
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "penshape/types/pen_sample.hpp"
#include "penshape/types/stroke.hpp"
#include "penshape/types/tablet_info.hpp"

namespace penshape::daemon {

// The device as the HID layer describes it: what a capture (hid-recorder header) needs.
struct HidDescription {
  std::vector<std::uint8_t> report_descriptor; // empty: unknown (the device cannot be captured)
  std::string name;                            // kernel HID name (N:)
  std::string phys;                            // physical path (P:)
  Bus bus = Bus::kUnknown;                     // I: bus vendor product
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::map<std::uint8_t, std::vector<std::uint8_t>> vendor_strings; // index -> string descriptor
};

struct DeviceDescriptor {
  std::string id;     // stable while attached, unique among attached devices ("hidraw3")
  TabletInfo tablet;  // maxima and resolution of its samples
  std::string source; // device path or recording file name
  bool replay = false;
  HidDescription hid{};
  // Whether tablet's resolution is a real physical size, and where it came from ("table",
  // "descriptor", "probe", "config"; "unknown" when it is not: coordinates are device units).
  bool physical_size_known = true;
  std::string size_source{}; // "" when the source does not say (an app's strokes, fakes)
  std::string family{};      // report family of the tablet table ("" for sources without one)
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
  // Whether anyone wants raw reports now. A source asks before each raw_report call, so a reader
  // thread copies nothing while nobody captures (a cheap, lock-free check).
  [[nodiscard]] virtual bool wants_raw_reports() const { return false; }
  // Every input report as the device sent it (before decoding, also those that decode to no
  // sample), before the samples it decodes to; time_us on the device's clock (the samples'
  // clock). `bytes` lives only for the call.
  virtual void raw_report(const std::string& /*device_id*/, std::span<const std::uint8_t> /*bytes*/,
                          std::int64_t /*time_us*/) {}
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
