#pragma once
// The drivers' DeviceManager as the daemon's SampleSource: live tablets (hotplug, one reader
// thread per device, the drivers' segmenter) and recordings replayed through the same path.
//
// The manager reports samples and finished strokes; this adapter adds the StrokeStarted the
// daemon publishes (at the first tip-down sample) and numbers strokes itself so the samples of a
// stroke and the finished stroke carry the same id. Every raw report goes to the sink as well, but
// only while the sink wants_raw_reports(): otherwise the reader thread pays one atomic load.
#include <atomic>
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include "penshape/daemon/sample_source.hpp"
#include "penshape/drivers/device_manager.hpp"

namespace penshape::daemon {

class DeviceManagerSource final : public SampleSource {
 public:
  // Physical sizes (width, height mm) by device key "vvvv:pppp" (the config's [device] sizes).
  using DeviceSizes = std::map<std::string, std::pair<double, double>>;

  // backend: the live devices (drivers::make_hidraw_backend()), or null for replays only.
  // sizes: used for a tablet that gives no physical size of its own.
  explicit DeviceManagerSource(std::unique_ptr<drivers::DeviceBackend> backend,
                               DeviceSizes sizes = {});
  ~DeviceManagerSource() override;

  void start(SampleSink& sink) override;
  void stop() override;
  [[nodiscard]] std::vector<DeviceDescriptor> devices() const override;

  // Replays a recording as a device (kOriginal: at its recorded pace, as if live). After start();
  // ignored once stop() has begun.
  void replay(const drivers::Recording& recording, drivers::ReplaySpeed speed);
  // Blocks until no device is attached (e.g. the replay ended) or the timeout passes.
  bool wait_until_idle(std::chrono::milliseconds timeout) const;

 private:
  struct Tracked {
    DeviceDescriptor descriptor;
    bool drawing = false;
    std::uint64_t stroke_id = 0;
    bool last_tip = false;
    std::int64_t last_time_us = 0;
  };
  void on_attach(const drivers::AttachedDevice& device);
  void on_detach(drivers::DeviceId id);
  void on_sample(drivers::DeviceId id, const PenSample& sample);
  void on_stroke(drivers::DeviceId id, Stroke&& stroke);
  void on_report(drivers::DeviceId id, std::span<const std::uint8_t> bytes, std::int64_t time_us);

  std::unique_ptr<drivers::DeviceBackend> backend_;
  DeviceSizes sizes_;
  std::unique_ptr<drivers::DeviceManager> manager_;
  SampleSink* sink_ = nullptr;
  mutable std::mutex mutex_;
  std::map<drivers::DeviceId, Tracked> tracked_;
  std::atomic<std::uint64_t> next_stroke_id_{1};
  std::mutex lifecycle_mutex_; // orders replay() against stop()
  bool stopped_ = false;
};

} // namespace penshape::daemon
