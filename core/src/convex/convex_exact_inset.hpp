#pragma once
// Internal: exact rational inward shifts of a convex polygon's edge lines (bracketing the
// irrational |n| by rationals) and their exact intersection: the slow, always-certified path.
#include <vector>

#include "geometry/segment_distance.hpp"
#include "penshape/core/polygon_set.hpp"

namespace penshape::detail {

// a·x + b·y <= c
struct HalfPlane {
  Rational a;
  Rational b;
  Rational c;
};

enum class ShiftBound { kUpper, kLower };

// The half-planes of a counterclockwise convex ring's edges, each shifted inward by `shift`
// times a rational bound on |(a, b)|: kUpper shifts at least `shift` (an inner region), kLower
// at most `shift` (an outer region). The bounds are within a relative 2^-precision_bits.
std::vector<HalfPlane> shifted_edge_half_planes(const Ring& ring, const Rational& shift,
                                                ShiftBound bound, unsigned precision_bits);

// The intersection of half-planes given in counterclockwise angular order (as produced above),
// as a counterclockwise ring; empty when the intersection has no interior.
Ring intersect_sorted_half_planes(const std::vector<HalfPlane>& planes);

} // namespace penshape::detail
