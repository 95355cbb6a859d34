#pragma once
// Douglas-Peucker simplification of integer rings, and its certified check: every dropped
// vertex lies within the tolerance of the chord that replaced it. That check is what lets the
// certificates use the simplified ring (README.md, "Simplified input"): moving each original
// point to its nearest point on the chord is a homotopy that moves no point farther than the
// tolerance, so the two regions are within that Hausdorff distance.
#include <optional>

#include "int_geometry.hpp"

namespace penshape::fast {

// Kept vertices are a subsequence of the input that starts with its first vertex.
IRing simplify_ring(const IRing& ring, double tolerance);

// Ring-wise simplification, returned only if every ring passes the tolerance check (certified:
// d <= tolerance, certified.hpp) and keeps at least three vertices and its orientation.
std::optional<IRings> simplify_rings_checked(const IRings& rings, double tolerance);

} // namespace penshape::fast
