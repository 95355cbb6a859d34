#pragma once
// Hold to snap on a live stroke in progress (live.proto's HoldSnap): HoldDetector tells, from the
// samples, when the pen held still (on the reader thread); HoldState is what that hold snapped,
// shared by the device's strand (which snaps the stroke so far and, at pen-up, publishes the
// final shape) and the reader thread (which makes the snapped shape follow the pen meanwhile).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "hold_follow.hpp"
#include "penshape/daemon/pen_settings.hpp"
#include "penshape/types/stroke.hpp"
#include "penshape/v1/live.pb.h"

namespace penshape::daemon {

// At most one follow update per this much of the tablet's clock (a display frame).
inline constexpr std::int64_t kFollowIntervalUs = 8000;

// A sample in millimetres (a resolution of 0, unknown, takes device units as millimetres, as the
// recognizer does).
PointMm sample_mm(const PenSample& s, const TabletInfo& tablet);

// Decides on the samples' own times, so a replay holds exactly as the live pen did.
class HoldDetector {
 public:
  HoldDetector(const PenSettings& settings, const TabletInfo& tablet)
      : hold_us_(static_cast<std::int64_t>(settings.hold_ms * 1000)),
        radius_mm_(settings.hold_radius_mm),
        tablet_(tablet) {}
  // A tip-down sample: true when the pen has now stayed within hold_radius_mm of one point for
  // hold_ms; the next hold then needs hold_ms more from the following sample.
  bool add(const PenSample& s);
  // After add() said true: when the pen came to rest (the hold's first sample's time). Also
  // while it rests (settled()).
  [[nodiscard]] std::int64_t held_since_us() const { return anchor_us_; }
  // True once per rest, after the add() at which the pen has rested a quarter of hold_ms: the
  // stroke drawn before the rest is then what a hold would snap, so the strand may recognize it
  // ahead (LiveGrouping::prepare_hold) and the hold publish at once.
  bool settled();

 private:
  std::int64_t hold_us_;
  double radius_mm_;
  TabletInfo tablet_;
  bool anchored_ = false;
  bool settle_told_ = false; // settled() said true for this rest
  std::int64_t last_us_ = 0; // the last add()'s sample time
  PointMm anchor_;
  std::int64_t anchor_us_ = 0;
};

struct HoldState {
  enum class Phase : std::uint8_t { kPending, kSnapped, kNothing };
  std::mutex mutex;
  Phase phase = Phase::kPending; // guarded by mutex; the fields below are set before kSnapped
  // Set when the hold is detected, constant after.
  std::size_t samples = 0;  // the stroke's samples up to the hold
  std::int64_t time_us = 0; // the hold's sample time (the tablet's clock)
  PointMm point;            // the tip where the pen held, mm
  double radius_mm = 0;
  // The snap, set by the strand.
  v1::Shape shape;
  std::uint64_t shape_id = 0;
  std::uint64_t sequence = 0; // its LiveEvent sequence
  std::vector<std::uint64_t> replaced_stroke_ids;
  std::vector<std::string> tidy;
  // The ink of the stroke up to the hold. A tablet's strand publishes the HOLD shape before Q is
  // built when the shape did not read it (ink_later), then fills `ink` after kSnapped: only that
  // strand reads `ink` (at release), never the reader thread's follow updates.
  v1::PolygonSet ink;
  std::function<v1::PolygonSet()> ink_later;
  std::string ink_error; // when building Q failed after the shape was out
  bool grouped = false;
  std::size_t answer = 0; // the grouping's id of this answer (when grouped)
};

// Where the pen went after the hold: whether it ever left hold_radius_mm of the hold point (else
// it was tremor, not a drag) and the last tip-down position.
struct Drag {
  bool dragged = false;
  PointMm tip;
  std::int64_t tip_time_us = 0;
};
Drag drag_after_hold(const Stroke& stroke, const HoldState& hold);

// The HoldSnap fields of a ShapeRecognized for this hold, the pen as `pen` says.
void set_hold_fields(const HoldState& hold, const Drag& pen, v1::ShapeRecognized* out);

// A FOLLOW or RELEASE event of a snapped hold: its shape moved by the drag (unmoved when the pen
// never left the hold radius), with the hold's shape_id, replaced strokes and tidy-up.
v1::LiveEvent hold_event(const std::string& device_id, std::uint64_t stroke_id,
                         const HoldState& hold, const Drag& drag, v1::ShapeTrigger trigger);

} // namespace penshape::daemon
