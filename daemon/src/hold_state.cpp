// Hold detection and the drag after a hold (hold_state.hpp).
#include "hold_state.hpp"

#include <cmath>

namespace penshape::daemon {
namespace {

double distance(PointMm a, PointMm b) { return std::hypot(a.x - b.x, a.y - b.y); }

} // namespace

PointMm sample_mm(const PenSample& s, const TabletInfo& tablet) {
  const double rx = tablet.x_resolution > 0 ? tablet.x_resolution : 1.0;
  const double ry = tablet.y_resolution > 0 ? tablet.y_resolution : 1.0;
  return {s.x / rx, s.y / ry};
}

bool HoldDetector::add(const PenSample& s) {
  last_us_ = s.time_us;
  const PointMm p = sample_mm(s, tablet_);
  if (!anchored_ || distance(p, anchor_) > radius_mm_ || s.time_us < anchor_us_) {
    anchored_ = true; // the pen moved: a hold starts here at the earliest
    settle_told_ = false;
    anchor_ = p;
    anchor_us_ = s.time_us;
    return false;
  }
  if (s.time_us - anchor_us_ < hold_us_) return false;
  anchored_ = false;
  return true;
}

bool HoldDetector::settled() {
  if (!anchored_ || settle_told_ || last_us_ - anchor_us_ < hold_us_ / 4) return false;
  settle_told_ = true;
  return true;
}

Drag drag_after_hold(const Stroke& stroke, const HoldState& hold) {
  Drag out{false, hold.point, hold.time_us};
  for (const PenSample& s : stroke.samples) {
    if (!s.tip || s.time_us <= hold.time_us) continue;
    out.tip = sample_mm(s, stroke.tablet);
    out.tip_time_us = s.time_us;
    if (distance(out.tip, hold.point) > hold.radius_mm) out.dragged = true;
  }
  return out;
}

void set_hold_fields(const HoldState& hold, const Drag& pen, v1::ShapeRecognized* out) {
  v1::HoldSnap* h = out->mutable_hold();
  h->set_certified_samples(static_cast<std::uint32_t>(hold.samples));
  h->mutable_hold_point()->set_x(hold.point.x);
  h->mutable_hold_point()->set_y(hold.point.y);
  h->mutable_pen_point()->set_x(pen.tip.x);
  h->mutable_pen_point()->set_y(pen.tip.y);
  h->set_adjusted(pen.dragged);
  h->set_held_shape_id(hold.shape_id);
  h->set_hold_time_us(hold.time_us);
  h->set_pen_time_us(pen.tip_time_us);
}

v1::LiveEvent hold_event(const std::string& device_id, std::uint64_t stroke_id,
                         const HoldState& hold, const Drag& drag, v1::ShapeTrigger trigger) {
  v1::LiveEvent event;
  event.set_device_id(device_id);
  v1::ShapeRecognized* s = event.mutable_shape();
  s->set_stroke_id(stroke_id);
  *s->mutable_shape() = drag.dragged ? follow_shape(hold.shape, hold.point, drag.tip) : hold.shape;
  s->set_shape_id(hold.shape_id);
  for (const std::uint64_t id : hold.replaced_stroke_ids) s->add_replaced_stroke_ids(id);
  for (const std::string& t : hold.tidy) s->add_tidy(t);
  s->set_trigger(trigger);
  set_hold_fields(hold, drag, s);
  return event;
}

} // namespace penshape::daemon
