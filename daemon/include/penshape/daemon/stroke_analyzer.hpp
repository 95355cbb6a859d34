#pragma once
// Turns a finished stroke into its ink polygon and recognized shape. The recognizer side
// implements it (ink polygon Q = stroke ⊕ pen disk, deconstruction, annulus fits) and converts
// its results to the penshape.v1 messages; the daemon runs it on the geometry workers for live
// strokes, SubmitStroke, StreamSamples and Geometry.Recognize, and asks it for previews while a
// live stroke is drawn.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/group_recognize.hpp"
#include "penshape/daemon/pen_settings.hpp"
#include "penshape/types/stroke.hpp"
#include "penshape/v1/geometry.pb.h"
#include "penshape/v1/shape.pb.h"
#include "penshape/v1/types.pb.h"

namespace penshape::daemon {

struct StrokeAnalysis {
  v1::PolygonSet ink_polygon; // mm
  // kind SHAPE_KIND_NONE when nothing is certified; SHAPE_KIND_UNSPECIFIED when the analyzer does
  // not recognize shapes (ink polygon only): then no ShapeRecognized is published.
  v1::Shape shape;
  std::vector<v1::Shape> alternatives;
};

// What adding one live stroke to its tablet's grouping gave (StrokeGroupSession::add).
struct GroupedStrokeAnalysis {
  // The new stroke's ink polygon; shape and alternatives: the answer that now covers the stroke
  // (certified on the union of its strokes when it covers several).
  StrokeAnalysis analysis;
  bool grouped = false;   // false: the stroke was not added to the grouping (a dot): alone
  std::size_t answer = 0; // the session's id of this answer (when grouped)
  std::vector<std::size_t> strokes;    // session indices of the strokes it covers, ascending
  std::vector<std::size_t> superseded; // session ids of the earlier answers it replaces
  std::vector<std::string> tidy;       // tidy-up constraints applied
  // Set only with InkOffload::shape_first when add() returned before the new stroke's ink
  // polygon was built (its answer read no Q): gives that ink (waits for or builds it; throws
  // its error). wait_ink() moves it into analysis.ink_polygon.
  std::function<v1::PolygonSet()> ink_later;
  void wait_ink() {
    if (!ink_later) return;
    analysis.ink_polygon = ink_later();
    ink_later = nullptr;
  }
};

// Where StrokeGroupSession::add() may build the new stroke's ink polygon while it fits the
// stroke's path (the recognizer needs Q only to certify, after fitting).
struct InkOffload {
  // Runs a job on another worker; false when none takes it. Empty, or a job not started by the
  // time Q is needed: add() builds Q itself.
  std::function<bool(std::function<void()>)> run_elsewhere;
  // add() may return before Q is built when its answer did not read Q (GroupedStrokeAnalysis::
  // ink_later): the shape goes out first, the ink when it exists.
  bool shape_first = false;
};

// One tablet's grouping of recent strokes (core's StrokeGrouper): strokes are added in drawing
// order, one at a time; a stroke decided to be writing (core's decide_intent on the recent
// strokes) is answered freeform, never recognized nor grouped, unless the pen's snap_writing; a
// session is not thread-safe (the pipeline runs one device's strokes in order on one worker at a
// time). Stroke indices count the strokes added (dots are not added).
class StrokeGroupSession {
 public:
  virtual ~StrokeGroupSession() = default;
  // The stroke's ink polygon (when `with_ink`: previews skip it) and its grouped answer. Throws
  // Cancelled when `cancel` asks to stop (the stroke is then not added). `offload` may build the
  // ink polygon on another worker meanwhile.
  virtual GroupedStrokeAnalysis add(const Stroke& stroke, bool with_ink, const CancelHook& cancel,
                                    const InkOffload& offload) = 0;
  GroupedStrokeAnalysis add(const Stroke& stroke, bool with_ink, const CancelHook& cancel) {
    return add(stroke, with_ink, cancel, {});
  }
  // The stroke so far of a hold (hold to snap): a hold is an explicit request to snap, so the
  // stroke is drawing whatever its writing score (add() leaves writing alone).
  virtual GroupedStrokeAnalysis add_held(const Stroke& stroke, const CancelHook& cancel,
                                         const InkOffload& offload) {
    return add(stroke, true, cancel, offload);
  }
  // An independent copy (a preview adds the stroke in progress to a copy).
  [[nodiscard]] virtual std::unique_ptr<StrokeGroupSession> clone() const = 0;
  [[nodiscard]] virtual std::size_t stroke_count() const = 0;
  // A session forgets the strokes no later stroke can reach (so a long session's memory follows
  // the grouping window, group_max_strokes and group_max_pause_s): the index of the oldest stroke
  // it still keeps (stroke_count() when none), and how many it keeps.
  [[nodiscard]] virtual std::size_t oldest_retained_stroke() const { return 0; }
  [[nodiscard]] virtual std::size_t retained_stroke_count() const { return stroke_count(); }
};

class StrokeAnalyzer {
 public:
  virtual ~StrokeAnalyzer() = default;
  // Called from worker threads, concurrently: must be thread-safe. Throws InvalidInput for a
  // stroke it refuses and Cancelled when `cancel` asks to stop.
  virtual StrokeAnalysis analyze(const Stroke& stroke, const PenSettings& settings,
                                 const CancelHook& cancel) = 0;
  // Several strokes in drawing order grouped into drawings (core's recognize_strokes, on the
  // strokes' paths in mm with the settings' pen radius): every stroke in exactly one group.
  // Throws InvalidInput naming `strokes[i]` for a stroke it refuses; analyzers that do not
  // recognize shapes return nothing (the caller reports UNIMPLEMENTED).
  virtual std::vector<v1::RecognizedGroup> recognize_group(const std::vector<Stroke>& /*strokes*/,
                                                           const PenSettings& /*settings*/,
                                                           const GroupingConfig& /*grouping*/) {
    return {};
  }
  // A new grouping of live strokes for one tablet, or null when this analyzer does not group
  // (then each live stroke is analysed alone by analyze()).
  virtual std::unique_ptr<StrokeGroupSession> group_session(const PenSettings& /*settings*/,
                                                            const GroupingConfig& /*grouping*/) {
    return nullptr;
  }
  // The shapes the stroke in progress would snap to if the pen lifted now, best first (the
  // on-line decision while points arrive). `partial` holds the samples so far. Called on a worker
  // at most once per Pipeline::kPreviewInterval per device, never twice at once for one device;
  // the default offers none.
  virtual std::vector<v1::Shape> preview(const Stroke& /*partial*/, const PenSettings& /*settings*/,
                                         const CancelHook& /*cancel*/) {
    return {};
  }
  // Work ahead on a live stroke while it is drawn (its ink polygon's chunks), reused by the
  // stroke's pen-up analysis. `partial` holds the samples so far. Called on a stroke worker now and
  // then, never twice at once for one stroke; optional: a pen-up does whatever was not done.
  virtual void work_ahead(const Stroke& /*partial*/, const PenSettings& /*settings*/,
                          const CancelHook& /*cancel*/) {}
};

} // namespace penshape::daemon
