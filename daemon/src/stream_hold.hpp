#pragma once
// Hold to snap on an app's StreamSamples stream (live_service.cpp): the stream's strokes are held,
// followed and released as a tablet's are (pipeline.cpp, live_grouping.cpp), on the stream's own
// thread: the hold is recognized as soon as the sample that satisfies it is read (the stream reads
// on after it), follow updates come with the samples after it, and at pen-up its final shape
// stands for the stroke's analysis.
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "hold_snap.hpp"

namespace penshape::daemon {

class StreamHold {
 public:
  // Off when snap_trigger is pen_up or there is no analyzer.
  StreamHold(const PenSettings& settings, bool has_analyzer)
      : settings_(settings),
        enabled_(has_analyzer && settings.snap_trigger != SnapTrigger::kPenUp),
        hold_only_(settings.snap_trigger == SnapTrigger::kHold) {}
  // snap_trigger = hold: a stroke that did not snap at a hold gets no ShapeRecognized.
  [[nodiscard]] bool hold_only() const { return hold_only_; }
  // A new stroke begins on `tablet`.
  void start(const TabletInfo& tablet);
  // After `stroke`'s last sample was added: the HOLD event when the hold is satisfied now and the
  // stroke so far snaps (`grouping` then holds it), a FOLLOW update when one is due, else nothing.
  std::optional<v1::LiveEvent> on_sample(const Stroke& stroke, GroupHistory& grouping,
                                         std::atomic<std::uint64_t>& next_shape_id,
                                         const CancelHook& cancel);
  // At pen-up, when the stroke's hold snapped: its StrokeFinished (the drawn part's ink) and
  // RELEASE events. Empty when it did not snap: the stroke is analysed as usual.
  std::vector<v1::LiveEvent> release(const Stroke& stroke, GroupHistory& grouping,
                                     std::atomic<std::uint64_t>& next_shape_id);

 private:
  PenSettings settings_;
  bool enabled_;
  bool hold_only_;
  std::optional<HoldDetector> detector_;
  std::unique_ptr<HoldState> hold_; // the stroke's snapped hold
  FollowGate gate_;
};

} // namespace penshape::daemon
