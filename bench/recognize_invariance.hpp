#pragma once
// What the recognizer's answers owe to the drawing and not to the device (recognize_bench
// --invariance): every labelled single-stroke drawing recognized as drawn, then moved far, scaled,
// retimed (nothing may change: the recognizer has no unit, origin or clock), turned, mirrored,
// drawn backwards (the same shape by the same hand), and as other devices would send it: at a
// half or a third of its sample rate, at four times it, jittered, on a coarse grid. Per
// transform: shapes named right, non-shapes snapped, and answers that differ from the drawing's
// own.
#include <vector>

#include "stroke_corpora.hpp"

namespace penshape::bench {

void print_invariance(const std::vector<Drawing>& drawings);

} // namespace penshape::bench
