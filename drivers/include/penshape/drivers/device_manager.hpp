#pragma once
// The device manager: finds pen tablets, initialises them (vendor protocols), reads each on its
// own blocking thread through the shared decode path (PenPipeline), and reports samples,
// finished strokes and attach/detach events through callbacks. Hotplug: the backend wakes the
// manager (libusb hotplug callbacks and a udev monitor for the live backend) and a slow rescan
// catches anything missed; there is no busy loop anywhere. A device that vanishes mid-stroke
// ends that stroke cleanly (delivered before its detach event) and comes back as a new attach
// when it reappears (replug, resume from suspend).
//
// Threading: callbacks run on the device's reader thread (attach on the hotplug thread, or on
// the caller's thread for attach_source/attach_replay). They must be quick and thread-safe; a
// daemon typically pushes into its own queues (DeviceEventQueue). Events of one device arrive
// in order: attach, samples and strokes, detach.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "penshape/drivers/device_profile.hpp"
#include "penshape/drivers/pen_pipeline.hpp"
#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/replay.hpp"
#include "penshape/drivers/report_source.hpp"

namespace penshape::drivers {

using DeviceId = std::uint64_t; // unique per manager, never reused (a replug gets a new one)

enum class DetachReason : std::uint8_t {
  kGone,    // unplugged, suspended or read error
  kEnded,   // the source ended (a replayed recording finished)
  kStopped, // the manager stopped
};

struct AttachedDevice {
  DeviceId id = 0;
  std::string key; // backend key, e.g. /dev/hidraw3, or "replay:N"
  TabletInfo tablet;
  Protocol protocol = Protocol::kHid;
  std::string family = "hid"; // report family (tablets.tsv / families.tsv)
  // Where tablet's resolution came from; kUnknown: its coordinates are device units only.
  SizeSource size_source = SizeSource::kUnknown;
  // What a capture's header needs: identity (kernel HID name when known), phys, the report
  // descriptor and the vendor strings read at open, as the device gave them (no events).
  Recording header{};
};

struct DeviceCallbacks {
  std::function<void(const AttachedDevice&)> on_attach;
  std::function<void(DeviceId, DetachReason, const PipelineCounters&)> on_detach;
  std::function<void(DeviceId, const PenSample&)> on_sample;
  std::function<void(DeviceId, Stroke&&)> on_stroke; // Stroke::id unique per manager
};

// Every input report as read (before decoding; also those that give no sample), on the reader
// thread before the samples it decodes to; the span lives only for the call. It runs once per
// report, so it must be cheap.
using DeviceReportCallback =
    std::function<void(DeviceId, std::span<const std::uint8_t>, std::int64_t time_us)>;

// A device as a backend sees it.
struct DeviceCandidate {
  std::string key; // stable while plugged
  DeviceIdentity identity;
  std::vector<std::uint8_t> descriptor;
  std::string hid_name{}; // the kernel's HID name (hid-recorder's N:), "" when unknown
  std::string phys{};     // the kernel's HID phys (hid-recorder's P:), "" when unknown
};

// Where devices come from. The live one is make_hidraw_backend(); tests inject fakes.
class DeviceBackend {
 public:
  virtual ~DeviceBackend() = default;
  // The devices present now (tablet interfaces; the manager drops those without a pen).
  virtual std::vector<DeviceCandidate> scan() = 0;
  // USB string descriptors (raw) a protocol needs; missing ones are left out.
  virtual VendorStrings read_vendor_strings(const DeviceCandidate& device,
                                            std::span<const std::uint8_t> indexes) = 0;
  // Opens the device and runs the init steps (feature/output reports). Throws on failure.
  virtual std::unique_ptr<ReportSource> open(const DeviceCandidate& device,
                                             const std::vector<InitStep>& init) = 0;
  // Blocks until a hotplug event, wake(), or the timeout.
  virtual void wait_for_change(std::chrono::milliseconds timeout) = 0;
  virtual void wake() = 0;
};

// hidapi (hidraw) enumeration, descriptors from sysfs or HIDIOCGRDESC, libusb for string
// descriptors and hotplug callbacks, a libudev monitor on the hidraw subsystem.
std::unique_ptr<DeviceBackend> make_hidraw_backend();

struct DeviceManagerOptions {
  SegmenterOptions segmenter;
  std::chrono::milliseconds rescan_interval{3000}; // fallback rescan when no event arrives
  std::chrono::milliseconds read_poll{100};        // bounds each blocking read
  // A device that just vanished is not reopened sooner than this (a node that keeps failing
  // right after open must not turn the rescan into a loop).
  std::chrono::milliseconds reattach_backoff{1000};
  // The user's physical size (width, height in mm) for a VID/PID, used only for a device whose
  // table row, descriptor and probe give none. May be empty.
  std::function<std::optional<std::pair<double, double>>(std::uint16_t, std::uint16_t)>
      configured_size;
};

class DeviceManager {
 public:
  // on_report: may be empty (then the read path has no extra call at all).
  DeviceManager(std::unique_ptr<DeviceBackend> backend, DeviceCallbacks callbacks,
                DeviceManagerOptions options = {}, DeviceReportCallback on_report = {});
  ~DeviceManager();
  DeviceManager(const DeviceManager&) = delete;
  DeviceManager& operator=(const DeviceManager&) = delete;

  // Starts the hotplug thread (which scans at once). Without a backend only sources attached
  // by hand are read.
  void start();
  // Stops every reader (open strokes end cleanly, then detach kStopped) and joins all threads.
  void stop();
  // Asks for a rescan now.
  void rescan();

  // Reads any source through the same path as a live device (e.g. a replay). Returns its id
  // or throws like build_profile (bad descriptor, unusable vendor strings).
  DeviceId attach_source(const DeviceIdentity& identity, std::span<const std::uint8_t> descriptor,
                         const VendorStrings& vendor_strings, std::unique_ptr<ReportSource> source,
                         std::string key = {});
  DeviceId attach_replay(const Recording& recording, ReplaySpeed speed);

  // The devices being read now.
  [[nodiscard]] std::vector<AttachedDevice> devices() const;
  // Blocks until no device is attached or the timeout passes; true when none is attached.
  bool wait_until_idle(std::chrono::milliseconds timeout) const;

 private:
  struct Device;
  void hotplug_loop();
  void scan_once();
  void reap_finished();
  // The profile with the configured physical size when it has none of its own.
  [[nodiscard]] DeviceProfile sized(DeviceProfile profile) const;
  DeviceId start_reader(AttachedDevice info, const DeviceProfile& profile,
                        std::unique_ptr<ReportSource> source);
  DeviceId attach_with_header(Recording header, std::unique_ptr<ReportSource> source,
                              std::string key);

  std::unique_ptr<DeviceBackend> backend_;
  DeviceCallbacks callbacks_;
  DeviceManagerOptions options_;
  DeviceReportCallback on_report_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::map<DeviceId, std::unique_ptr<Device>> devices_;
  std::map<std::string, std::chrono::steady_clock::time_point> gone_at_; // key -> last vanish
  std::atomic<DeviceId> next_id_{1};
  std::atomic<std::uint64_t> next_stroke_id_{1};
  std::atomic<bool> stopping_{false};
  std::thread hotplug_;
};

} // namespace penshape::drivers
