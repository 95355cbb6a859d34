// The hold's recognition step and the follow updates' pace (hold_snap.hpp).
#include "hold_snap.hpp"

#include <cmath>
#include <utility>

namespace penshape::daemon {

HoldTrial try_hold(const GroupHistory& history, const Stroke& partial, const CancelHook& cancel,
                   const InkOffload& offload) {
  HoldTrial trial{history.copy(), {}};
  trial.result = trial.history.add_held(partial, cancel, offload); // a hold: drawing
  return trial;
}

std::optional<v1::LiveEvent> take_hold(GroupHistory& history, HoldTrial trial,
                                       std::uint64_t stroke_id, HoldState& hold,
                                       std::atomic<std::uint64_t>& next_shape_id) {
  GroupedStrokeAnalysis& result = trial.result;
  const v1::ShapeKind kind = result.analysis.shape.kind();
  if (kind == v1::SHAPE_KIND_NONE || kind == v1::SHAPE_KIND_UNSPECIFIED) return std::nullopt;
  const GroupAnswer answer = trial.history.take(result, stroke_id);
  hold.shape = std::move(result.analysis.shape);
  hold.shape.mutable_certificate()->set_scope("drawn_part");
  hold.shape_id = ++next_shape_id;
  hold.replaced_stroke_ids = answer.replaced_stroke_ids;
  hold.tidy = result.tidy;
  if (result.ink_later) {
    hold.ink_later = std::move(result.ink_later); // the shape goes out first (InkOffload)
  } else {
    hold.ink = std::move(result.analysis.ink_polygon);
  }
  hold.grouped = result.grouped;
  hold.answer = result.answer;
  v1::LiveEvent event;
  v1::ShapeRecognized* s = event.mutable_shape();
  s->set_stroke_id(stroke_id);
  *s->mutable_shape() = hold.shape;
  for (auto& alternative : result.analysis.alternatives) s->add_alternatives()->Swap(&alternative);
  set_group_fields(answer, result.tidy, hold.shape_id, s);
  for (const std::uint64_t q : answer.supersedes_sequences) s->add_supersedes_sequences(q);
  s->set_trigger(v1::SHAPE_TRIGGER_HOLD);
  set_hold_fields(hold, {false, hold.point, hold.time_us}, s);
  trial.history.remember(result, hold.shape_id, 0);
  history = std::move(trial.history);
  return event;
}

std::optional<v1::LiveEvent> snap_at_hold(GroupHistory& history, const Stroke& partial,
                                          HoldState& hold,
                                          std::atomic<std::uint64_t>& next_shape_id,
                                          const CancelHook& cancel, const InkOffload& offload) {
  if (history.session() == nullptr) return std::nullopt; // the analyzer does not group
  return take_hold(history, try_hold(history, partial, cancel, offload), partial.id, hold,
                   next_shape_id);
}

void FollowGate::see(const HoldState& hold, PointMm tip) {
  if (std::hypot(tip.x - hold.point.x, tip.y - hold.point.y) > hold.radius_mm) dragging_ = true;
}

bool FollowGate::due(std::int64_t time_us) {
  if (!dragging_ || (sent_ && time_us - last_us_ < kFollowIntervalUs)) return false;
  sent_ = true;
  last_us_ = time_us;
  return true;
}

} // namespace penshape::daemon
