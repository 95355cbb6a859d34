// Hold to snap on a StreamSamples stream (stream_hold.hpp).
#include "stream_hold.hpp"

#include "penshape/daemon/proto_convert.hpp"

namespace penshape::daemon {

void StreamHold::start(const TabletInfo& tablet) {
  hold_.reset();
  gate_ = {};
  detector_.reset();
  if (enabled_) detector_.emplace(settings_, tablet);
}

std::optional<v1::LiveEvent> StreamHold::on_sample(const Stroke& stroke, GroupHistory& grouping,
                                                   std::atomic<std::uint64_t>& next_shape_id,
                                                   const CancelHook& cancel) {
  if (!detector_ || stroke.samples.empty() || !stroke.samples.back().tip) return std::nullopt;
  const PenSample& s = stroke.samples.back();
  const PointMm tip = sample_mm(s, stroke.tablet);
  if (hold_) {
    gate_.see(*hold_, tip);
    if (!gate_.due(s.time_us)) return std::nullopt;
    return hold_event("stream", stroke.id, *hold_, {true, tip, s.time_us},
                      v1::SHAPE_TRIGGER_FOLLOW);
  }
  if (!detector_->add(s)) return std::nullopt;
  auto hold = std::make_unique<HoldState>();
  hold->time_us = s.time_us;
  hold->point = tip;
  hold->radius_mm = settings_.hold_radius_mm;
  Stroke partial = stroke; // what was drawn before the pen came to rest
  while (partial.samples.size() > 2 &&
         partial.samples.back().time_us > detector_->held_since_us()) {
    partial.samples.pop_back();
  }
  hold->samples = partial.samples.size();
  std::optional<v1::LiveEvent> event;
  try {
    event = snap_at_hold(grouping, partial, *hold, next_shape_id, cancel, {});
  } catch (const std::exception&) {
    return std::nullopt; // refused or cancelled: as if the pen had not held
  }
  if (!event) return std::nullopt; // nothing certified: a later hold may snap
  hold_ = std::move(hold);
  gate_ = {};
  return event;
}

std::vector<v1::LiveEvent> StreamHold::release(const Stroke& stroke, GroupHistory& grouping,
                                               std::atomic<std::uint64_t>& next_shape_id) {
  std::vector<v1::LiveEvent> out;
  if (!hold_) return out;
  v1::LiveEvent finished;
  to_proto(stroke, finished.mutable_stroke_finished()->mutable_stroke());
  *finished.mutable_stroke_finished()->mutable_ink_polygon() = hold_->ink;
  out.push_back(std::move(finished));
  const Drag drag = drag_after_hold(stroke, *hold_);
  v1::LiveEvent event = hold_event("stream", stroke.id, *hold_, drag, v1::SHAPE_TRIGGER_RELEASE);
  if (drag.dragged) { // a new answer, superseding the hold's
    const std::uint64_t id = ++next_shape_id;
    event.mutable_shape()->set_shape_id(id);
    event.mutable_shape()->add_supersedes_shape_ids(hold_->shape_id);
    event.mutable_shape()->add_supersedes_sequences(0); // the stream's events are not published
    if (hold_->grouped) grouping.rename(hold_->answer, id, 0);
  }
  out.push_back(std::move(event));
  hold_.reset();
  return out;
}

} // namespace penshape::daemon
