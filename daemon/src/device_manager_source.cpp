#include "penshape/daemon/device_manager_source.hpp"

#include "log.hpp"
#include "penshape/daemon/pen_settings.hpp"

namespace penshape::daemon {

DeviceManagerSource::DeviceManagerSource(std::unique_ptr<drivers::DeviceBackend> backend,
                                         DeviceSizes sizes)
    : backend_(std::move(backend)), sizes_(std::move(sizes)) {}

DeviceManagerSource::~DeviceManagerSource() { stop(); }

void DeviceManagerSource::start(SampleSink& sink) {
  sink_ = &sink;
  drivers::DeviceCallbacks callbacks;
  callbacks.on_attach = [this](const drivers::AttachedDevice& d) { on_attach(d); };
  callbacks.on_detach = [this](drivers::DeviceId id, drivers::DetachReason,
                               const drivers::PipelineCounters&) { on_detach(id); };
  callbacks.on_sample = [this](drivers::DeviceId id, const PenSample& s) { on_sample(id, s); };
  callbacks.on_stroke = [this](drivers::DeviceId id, Stroke&& s) { on_stroke(id, std::move(s)); };
  const bool live = backend_ != nullptr;
  drivers::DeviceManagerOptions options;
  options.configured_size = [this](std::uint16_t vid, std::uint16_t pid) {
    const auto it = sizes_.find(device_key(vid, pid));
    return it == sizes_.end() ? std::nullopt : std::optional<std::pair<double, double>>(it->second);
  };
  manager_ = std::make_unique<drivers::DeviceManager>(
      std::move(backend_), std::move(callbacks), std::move(options),
      [this](drivers::DeviceId id, std::span<const std::uint8_t> bytes, std::int64_t t) {
        on_report(id, bytes, t);
      });
  if (live) manager_->start();
}

void DeviceManagerSource::stop() {
  std::lock_guard lock(lifecycle_mutex_);
  stopped_ = true;
  // The manager ends open strokes cleanly (on_stroke), then detaches, then joins its threads.
  if (manager_) manager_->stop();
}

std::vector<DeviceDescriptor> DeviceManagerSource::devices() const {
  std::lock_guard lock(mutex_);
  std::vector<DeviceDescriptor> out;
  for (const auto& [id, t] : tracked_) out.push_back(t.descriptor);
  return out;
}

void DeviceManagerSource::replay(const drivers::Recording& recording, drivers::ReplaySpeed speed) {
  std::lock_guard lock(lifecycle_mutex_);
  if (stopped_ || !manager_) return;
  manager_->attach_replay(recording, speed);
}

bool DeviceManagerSource::wait_until_idle(std::chrono::milliseconds timeout) const {
  return manager_->wait_until_idle(timeout);
}

void DeviceManagerSource::on_attach(const drivers::AttachedDevice& device) {
  DeviceDescriptor d;
  d.id = device.key.empty() ? "device:" + std::to_string(device.id) : device.key;
  if (d.id.rfind("/dev/", 0) == 0) d.id = d.id.substr(5); // "hidraw3"
  d.tablet = device.tablet;
  d.source = device.key;
  d.replay = device.key.rfind("replay", 0) == 0;
  const drivers::Recording& h = device.header;
  d.hid.report_descriptor = h.descriptor;
  d.hid.name = h.identity.name;
  d.hid.phys = h.phys;
  if (h.has_identity) {
    d.hid.bus = h.identity.bus;
    d.hid.vendor_id = h.identity.vendor_id;
    d.hid.product_id = h.identity.product_id;
  }
  d.hid.vendor_strings = h.vendor_strings;
  d.family = device.family;
  d.size_source = drivers::size_source_name(device.size_source);
  d.physical_size_known = device.size_source != drivers::SizeSource::kUnknown;
  if (!d.physical_size_known) {
    log(LogLevel::kWarning,
        "tablet " + d.id + " (" + device_key(d.tablet.vendor_id, d.tablet.product_id) + ", " +
            d.tablet.name + ") gives no physical size: its pen radius and tolerance cannot be " +
            "millimetres; set width_mm and height_mm in [device.\"" +
            device_key(d.tablet.vendor_id, d.tablet.product_id) + "\"] of the config file");
  }
  {
    std::lock_guard lock(mutex_);
    tracked_[device.id].descriptor = d;
  }
  sink_->device_attached(d);
}

void DeviceManagerSource::on_detach(drivers::DeviceId id) {
  std::string name;
  {
    std::lock_guard lock(mutex_);
    const auto it = tracked_.find(id);
    if (it == tracked_.end()) return;
    name = it->second.descriptor.id;
    tracked_.erase(it);
  }
  sink_->device_detached(name);
}

void DeviceManagerSource::on_sample(drivers::DeviceId id, const PenSample& sample) {
  std::string name;
  std::uint64_t stroke_id = 0;
  bool started = false;
  {
    std::lock_guard lock(mutex_);
    const auto it = tracked_.find(id);
    if (it == tracked_.end()) return;
    Tracked& t = it->second;
    if (sample.tip && !t.drawing) {
      t.drawing = true;
      t.stroke_id = next_stroke_id_++;
      started = true;
    }
    t.last_tip = sample.tip;
    t.last_time_us = sample.time_us;
    name = t.descriptor.id;
    stroke_id = t.drawing ? t.stroke_id : 0;
  }
  if (started) sink_->stroke_started(name, stroke_id);
  sink_->sample(name, stroke_id, sample);
}

void DeviceManagerSource::on_report(drivers::DeviceId id, std::span<const std::uint8_t> bytes,
                                    std::int64_t time_us) {
  if (!sink_->wants_raw_reports()) return;
  std::string name;
  {
    std::lock_guard lock(mutex_);
    const auto it = tracked_.find(id);
    if (it == tracked_.end()) return;
    name = it->second.descriptor.id;
  }
  sink_->raw_report(name, bytes, time_us);
}

void DeviceManagerSource::on_stroke(drivers::DeviceId id, Stroke&& stroke) {
  std::string name;
  std::uint64_t next_id = 0;
  {
    std::lock_guard lock(mutex_);
    const auto it = tracked_.find(id);
    if (it == tracked_.end()) return;
    Tracked& t = it->second;
    name = t.descriptor.id;
    stroke.id = t.drawing ? t.stroke_id : next_stroke_id_++;
    t.drawing = false;
    // The segmenter reports a stroke after the sample that ended it; when that sample already put
    // the tip down again (after the debounce window), a new stroke has begun with it.
    const bool restarted =
        t.last_tip && !stroke.samples.empty() && t.last_time_us > stroke.samples.back().time_us;
    if (restarted) {
      t.drawing = true;
      t.stroke_id = next_stroke_id_++;
      next_id = t.stroke_id;
    }
  }
  sink_->stroke_finished(name, std::move(stroke));
  if (next_id != 0) sink_->stroke_started(name, next_id);
}

} // namespace penshape::daemon
