#pragma once
// Internal exact distance and orientation helpers on rational points.
#include "penshape/core/polygon_set.hpp"

namespace penshape::detail {

// Squared distance from p to the segment [s, t], exactly.
Rational squared_distance_to_segment(const ExactPoint& p, const ExactPoint& s, const ExactPoint& t);

// Sign of the turn a → b → c: +1 left, -1 right, 0 collinear.
int orientation(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c);

// Do the closed segments [a, b] and [c, d] share a point?
bool segments_meet(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c,
                   const ExactPoint& d);

// Is p strictly inside the ring (even-odd rule)? p must not lie on the ring.
bool strictly_inside_ring(const ExactPoint& p, const Ring& ring);

} // namespace penshape::detail
