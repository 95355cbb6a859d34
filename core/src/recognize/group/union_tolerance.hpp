#pragma once
// The tolerance of a union of strokes from the strokes' bounding boxes: the grouper tries many
// unions of the same recent strokes, and choose_tolerance()'s rule depends only on the samples'
// box (tolerance_for_box), so each stroke's box is measured once instead of gathering every
// sample of every candidate union.
#include <span>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::recognize_detail {

// The smallest axis-parallel box holding a stroke's samples.
struct SampleBox {
  PointD lo, hi;
};

// choose_tolerance() on all the boxes' samples together, bit for bit: the union's box is exact
// (a minimum and a maximum of the same doubles).
ToleranceChoice union_tolerance(std::span<const SampleBox> boxes, const RecognizerConfig& config);

} // namespace penshape::recognize_detail
