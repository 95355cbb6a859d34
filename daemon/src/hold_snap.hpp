#pragma once
// Hold to snap's recognition step, shared by a tablet's strand (live_grouping.cpp) and an app's
// StreamSamples stream (stream_hold.cpp): the stroke so far is added to a copy of its grouping, and
// only a certified shape makes that copy the grouping (the stroke then counts as drawn up to the
// hold); otherwise nothing changes.
#include <atomic>
#include <cstdint>
#include <optional>

#include "group_history.hpp"
#include "hold_state.hpp"

namespace penshape::daemon {

// The stroke up to a hold recognized on a copy of a grouping (not yet taken: nothing published).
struct HoldTrial {
  GroupHistory history; // the copy, with the stroke added
  GroupedStrokeAnalysis result;
};
// Recognizes `partial` with `history`'s recent strokes, on a copy. Throws as
// StrokeGroupSession::add. `history` must group (session() non-null).
HoldTrial try_hold(const GroupHistory& history, const Stroke& partial, const CancelHook& cancel,
                   const InkOffload& offload);
// snap_at_hold's second half: `trial` (of `history` as it is now, for the stroke `stroke_id`)
// taken as the hold's answer when it is a certified shape.
std::optional<v1::LiveEvent> take_hold(GroupHistory& history, HoldTrial trial,
                                       std::uint64_t stroke_id, HoldState& hold,
                                       std::atomic<std::uint64_t>& next_shape_id);

// Recognizes `partial` (the stroke up to the hold) with `history`'s recent strokes. On a certified
// shape, fills `hold` (the shape, its certificate's scope "drawn_part", its new shape_id, replaced
// strokes, tidy-up, ink) and returns its HOLD event (device id and timings left to the caller, who
// publishes it, then calls history.rename(hold.answer, hold.shape_id, sequence)); otherwise
// returns nothing. Throws as StrokeGroupSession::add (nothing changed then).
std::optional<v1::LiveEvent> snap_at_hold(GroupHistory& history, const Stroke& partial,
                                          HoldState& hold,
                                          std::atomic<std::uint64_t>& next_shape_id,
                                          const CancelHook& cancel, const InkOffload& offload);

// When a snapped hold's shape follows the pen: once the pen has left hold_radius_mm of the hold
// point (tremor within it is not a drag), at most one update per kFollowIntervalUs of the
// tablet's clock.
class FollowGate {
 public:
  // The pen at `tip`: is it dragging now?
  void see(const HoldState& hold, PointMm tip);
  // True when an update is due at `time_us` (then counted).
  bool due(std::int64_t time_us);
  [[nodiscard]] bool dragging() const { return dragging_; }

 private:
  bool dragging_ = false;
  bool sent_ = false;
  std::int64_t last_us_ = 0;
};

} // namespace penshape::daemon
