#pragma once
// Certified thinning of the pen path (recognize.hpp, "Dense strokes"): a sub-path A' of the
// samples A with H(A, A') <= tau, so that a dense stroke costs what its shape costs.
#include <span>
#include <vector>

#include "recognize/fitting/geometry.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {

// Douglas-Peucker on windows of at most kThinWindow consecutive points (window ends are always
// kept), so the worst case is linear in the number of points: every dropped point lies within
// tau of the chord of the two kept points around it. First and last points are kept; tau <= 0
// returns the path unchanged.
std::vector<PointD> thin_path(std::span<const PointD> path, double tau);

} // namespace penshape::recognize_detail
