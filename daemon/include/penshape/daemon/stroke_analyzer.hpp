#pragma once
// Turns a finished stroke into its ink polygon and recognized shape. The recognizer side
// implements it (ink polygon Q = stroke ⊕ pen disk, deconstruction, annulus fits) and converts
// its results to the penshape.v1 messages; the daemon runs it on the geometry workers for live
// strokes, SubmitStroke, StreamSamples and Geometry.Recognize, and asks it for previews while a
// live stroke is drawn.
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

class StrokeAnalyzer {
 public:
  virtual ~StrokeAnalyzer() = default;
  // Called from worker threads, concurrently: must be thread-safe. Throws InvalidInput for a
  // stroke it refuses and Cancelled when `cancel` asks to stop.
  virtual StrokeAnalysis analyze(const Stroke& stroke, const PenSettings& settings,
                                 const CancelHook& cancel) = 0;
  // The shapes the stroke in progress would snap to if the pen lifted now, best first (the
  // on-line decision while points arrive). `partial` holds the samples so far. Called on a worker
  // at most once per Pipeline::kPreviewInterval per device, never twice at once for one device;
  // the default offers none.
  // Several strokes in drawing order grouped into drawings (core's recognize_strokes, on the
  // strokes' paths in mm with the settings' pen radius): every stroke in exactly one group.
  // Throws InvalidInput naming `strokes[i]` for a stroke it refuses; analyzers that do not
  // recognize shapes return nothing (the caller reports UNIMPLEMENTED).
  virtual std::vector<v1::RecognizedGroup> recognize_group(const std::vector<Stroke>& /*strokes*/,
                                                           const PenSettings& /*settings*/,
                                                           const GroupingConfig& /*grouping*/) {
    return {};
  }
  virtual std::vector<v1::Shape> preview(const Stroke& /*partial*/, const PenSettings& /*settings*/,
                                         const CancelHook& /*cancel*/) {
    return {};
  }
};

} // namespace penshape::daemon
