#include "daemon_state.hpp"

#include "penshape/daemon/proto_convert.hpp"

namespace penshape::daemon {

void DeviceRegistry::add(const DeviceDescriptor& device) {
  std::lock_guard lock(mutex_);
  devices_[device.id] = device;
}

void DeviceRegistry::remove(const std::string& id) {
  std::lock_guard lock(mutex_);
  devices_.erase(id);
}

std::vector<DeviceDescriptor> DeviceRegistry::list() const {
  std::lock_guard lock(mutex_);
  std::vector<DeviceDescriptor> out;
  for (const auto& [id, device] : devices_) out.push_back(device);
  return out;
}

bool DeviceRegistry::find(const std::string& id, DeviceDescriptor* out) const {
  std::lock_guard lock(mutex_);
  const auto it = devices_.find(id);
  if (it == devices_.end()) return false;
  *out = it->second;
  return true;
}

void to_proto(const DeviceDescriptor& device, v1::DeviceInfo* out) {
  out->set_id(device.id);
  out->set_settings_key(device_key(device.tablet.vendor_id, device.tablet.product_id));
  to_proto(device.tablet, out->mutable_tablet());
  out->set_source(device.source);
  out->set_replay(device.replay);
  out->set_physical_size_known(device.physical_size_known);
  out->set_size_source(device.size_source);
  out->set_family(device.family);
  const HidDescription& hid = device.hid;
  if (hid.report_descriptor.empty()) return; // nothing to capture a device by
  v1::HidFacts* facts = out->mutable_hid();
  facts->set_report_descriptor(hid.report_descriptor.data(), hid.report_descriptor.size());
  facts->set_name(hid.name);
  facts->set_phys(hid.phys);
  facts->set_bus(static_cast<std::uint32_t>(hid.bus));
  facts->set_vendor_id(hid.vendor_id);
  facts->set_product_id(hid.product_id);
  for (const auto& [index, bytes] : hid.vendor_strings) {
    v1::VendorString* s = facts->add_vendor_strings();
    s->set_index(index);
    s->set_data(bytes.data(), bytes.size());
  }
}

PenSettings settings_for(const DaemonState& state, const TabletInfo& tablet) {
  return state.settings.effective(device_key(tablet.vendor_id, tablet.product_id));
}

void publish_stroke(ShapeHub& hub, const std::string& device_id, const Stroke& stroke,
                    const StrokeAnalysis* analysis, const std::string& not_analysed,
                    const v1::Timings& timings) {
  publish_stroke(hub, device_id, stroke, analysis, not_analysed, timings, {});
}

std::uint64_t publish_stroke(ShapeHub& hub, const std::string& device_id, const Stroke& stroke,
                             const StrokeAnalysis* analysis, const std::string& not_analysed,
                             const v1::Timings& timings,
                             const std::function<void(v1::ShapeRecognized&)>& decorate) {
  v1::LiveEvent finished;
  finished.set_device_id(device_id);
  v1::StrokeFinished* f = finished.mutable_stroke_finished();
  to_proto(stroke, f->mutable_stroke());
  if (analysis != nullptr) *f->mutable_ink_polygon() = analysis->ink_polygon;
  f->set_not_analysed(not_analysed);
  hub.publish(std::move(finished));
  if (analysis == nullptr || analysis->shape.kind() == v1::SHAPE_KIND_UNSPECIFIED) return 0;
  v1::LiveEvent shape;
  shape.set_device_id(device_id);
  v1::ShapeRecognized* s = shape.mutable_shape();
  s->set_stroke_id(stroke.id);
  *s->mutable_shape() = analysis->shape;
  for (const auto& alternative : analysis->alternatives) *s->add_alternatives() = alternative;
  *s->mutable_timings() = timings;
  if (decorate) decorate(*s);
  return hub.publish(std::move(shape));
}

InkOffload ink_offload(WorkerPool& pool) {
  InkOffload offload;
  offload.run_elsewhere = [&pool](std::function<void()> job) {
    return pool.submit([job = std::move(job)](const StopCondition& /*unused*/) { job(); });
  };
  return offload;
}

void publish_raw_report(ShapeHub& hub, const std::string& device_id,
                        std::span<const std::uint8_t> bytes, std::int64_t time_us) {
  v1::LiveEvent event;
  event.set_device_id(device_id);
  v1::RawReport* report = event.mutable_raw_report();
  report->set_data(bytes.data(), bytes.size());
  report->set_time_us(time_us);
  hub.publish(std::move(event));
}

} // namespace penshape::daemon
