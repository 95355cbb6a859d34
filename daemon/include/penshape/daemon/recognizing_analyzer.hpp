#pragma once
// The daemon's stroke analyzer: the ink polygon (penshape::ink_polygon) and the certified shape
// (penshape::recognize, annulus fits), both in millimetres. The pen radius comes from the
// settings; the recognition tolerance follows the recognizer's documented rule (a fraction of
// the drawing's size plus the pen radius, bounded by a fraction of the size:
// choose_tolerance, core/include/penshape/core/recognize.hpp).
// Previews run the live recognizer on the samples so far, one per stroke in progress.
#include <memory>

#include "penshape/core/recognize.hpp"
#include "penshape/daemon/stroke_analyzer.hpp"

namespace penshape::daemon {

std::shared_ptr<StrokeAnalyzer> make_recognizing_analyzer();

// The penshape.v1 form of a recognizer candidate (kind NONE for freeform), coordinates in mm.
v1::Shape to_proto_shape(ShapeClass shape, const ShapeParams& params,
                         const std::vector<PointD>& clean, const Certificate& certificate,
                         double confidence);

} // namespace penshape::daemon
