// penshape.v1 pen messages <-> core value types (pen_types.hpp).
#include "penshape/proto/pen_types.hpp"

#include <algorithm>

namespace penshape::proto {
namespace {

std::int16_t tilt_from(std::int32_t degrees) {
  return static_cast<std::int16_t>(std::clamp(degrees, -kMaxTiltDegrees, kMaxTiltDegrees));
}

} // namespace

PenSample from_proto(const v1::PenSample& m) {
  PenSample s;
  s.time_us = m.time_us();
  s.x = m.x();
  s.y = m.y();
  s.pressure = m.pressure();
  s.tilt_x = tilt_from(m.tilt_x());
  s.tilt_y = tilt_from(m.tilt_y());
  s.buttons = m.buttons();
  s.in_range = m.in_range();
  s.tip = m.tip();
  return s;
}

TabletInfo from_proto(const v1::TabletInfo& m) {
  TabletInfo t;
  t.bus = static_cast<Bus>(m.bus());
  t.vendor_id = static_cast<std::uint16_t>(m.vendor_id());
  t.product_id = static_cast<std::uint16_t>(m.product_id());
  t.name = m.name();
  t.x_max = m.x_max();
  t.y_max = m.y_max();
  t.pressure_max = m.pressure_max();
  t.x_resolution = m.x_resolution();
  t.y_resolution = m.y_resolution();
  t.has_tilt = m.has_tilt();
  return t;
}

void to_proto(const PenSample& s, v1::PenSample* out) {
  out->set_time_us(s.time_us);
  out->set_x(s.x);
  out->set_y(s.y);
  out->set_pressure(s.pressure);
  out->set_tilt_x(s.tilt_x);
  out->set_tilt_y(s.tilt_y);
  out->set_buttons(s.buttons);
  out->set_in_range(s.in_range);
  out->set_tip(s.tip);
}

void to_proto(const TabletInfo& t, v1::TabletInfo* out) {
  out->set_bus(static_cast<v1::Bus>(t.bus));
  out->set_vendor_id(t.vendor_id);
  out->set_product_id(t.product_id);
  out->set_name(t.name);
  out->set_x_max(t.x_max);
  out->set_y_max(t.y_max);
  out->set_pressure_max(t.pressure_max);
  out->set_x_resolution(t.x_resolution);
  out->set_y_resolution(t.y_resolution);
  out->set_has_tilt(t.has_tilt);
}

void to_proto(const Stroke& stroke, v1::Stroke* out) {
  out->set_id(stroke.id);
  to_proto(stroke.tablet, out->mutable_tablet());
  out->mutable_samples()->Reserve(static_cast<int>(stroke.samples.size()));
  for (const PenSample& s : stroke.samples) to_proto(s, out->add_samples());
}

} // namespace penshape::proto
