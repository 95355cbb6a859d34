#pragma once
// The exact point-to-segment distance on rational points (the kernel's rational instance of
// distance_kernel.hpp, compiled once). Orientation and segment intersection are in
// exact_predicates.hpp.
#include "penshape/core/polygon_set.hpp"

namespace penshape::detail {

// Squared distance from p to the segment [s, t], exactly.
Rational squared_distance_to_segment(const ExactPoint& p, const ExactPoint& s, const ExactPoint& t);

} // namespace penshape::detail
