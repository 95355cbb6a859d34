#pragma once
// Exact predicates on double inputs: a floating-point filter with a conservative error bound,
// falling back to GMP rationals when the filter cannot decide.
#include "penshape/core/polygon_set.hpp"

namespace penshape::annulus::detail {

// Sign of the orientation of (a, b, c): +1 left turn, -1 right turn, 0 collinear. Exact.
int orientation(PointD a, PointD b, PointD c);

// Do the closed segments ab and cd share a point? Exact.
bool segments_intersect(PointD a, PointD b, PointD c, PointD d);

} // namespace penshape::annulus::detail
