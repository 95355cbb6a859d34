// The hold's recognition step and the follow updates' pace (hold_snap.hpp).
#include "hold_snap.hpp"

#include <cmath>
#include <utility>

namespace penshape::daemon {

std::optional<v1::LiveEvent> snap_at_hold(GroupHistory& history, const Stroke& partial,
                                          HoldState& hold,
                                          std::atomic<std::uint64_t>& next_shape_id,
                                          const CancelHook& cancel, const InkOffload& offload) {
  if (history.session() == nullptr) return std::nullopt; // the analyzer does not group
  GroupHistory trial = history.copy();
  GroupedStrokeAnalysis result = trial.add_held(partial, cancel, offload); // a hold: drawing
  const v1::ShapeKind kind = result.analysis.shape.kind();
  if (kind == v1::SHAPE_KIND_NONE || kind == v1::SHAPE_KIND_UNSPECIFIED) return std::nullopt;
  const GroupAnswer answer = trial.take(result, partial.id);
  hold.shape = std::move(result.analysis.shape);
  hold.shape.mutable_certificate()->set_scope("drawn_part");
  hold.shape_id = ++next_shape_id;
  hold.replaced_stroke_ids = answer.replaced_stroke_ids;
  hold.tidy = result.tidy;
  hold.ink = result.analysis.ink_polygon;
  hold.grouped = result.grouped;
  hold.answer = result.answer;
  v1::LiveEvent event;
  v1::ShapeRecognized* s = event.mutable_shape();
  s->set_stroke_id(partial.id);
  *s->mutable_shape() = hold.shape;
  for (auto& alternative : result.analysis.alternatives) s->add_alternatives()->Swap(&alternative);
  set_group_fields(answer, result.tidy, hold.shape_id, s);
  for (const std::uint64_t q : answer.supersedes_sequences) s->add_supersedes_sequences(q);
  s->set_trigger(v1::SHAPE_TRIGGER_HOLD);
  set_hold_fields(hold, {false, hold.point, hold.time_us}, s);
  trial.remember(result, hold.shape_id, 0);
  history = std::move(trial);
  return event;
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
