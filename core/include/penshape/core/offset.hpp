#pragma once
// Exact offsets and insets of polygonal regions by convex polygons (in practice the disk
// approximations D̄_{a,b} of disk_approximation.hpp), on exact rationals (CGAL Minkowski sums and
// Boolean set operations inside core). With K = D̄_{a,b}:
//   offset(X, a) ⊆ offset_by(X, K) ⊆ offset(X, b)   and   inset(X, b) ⊆ inset_by(X, K) ⊆ inset(X,
//   a).
#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_set.hpp"

namespace penshape {

// X ⊕ K. X: a valid region (validate_region), any orientation; K: a convex counterclockwise ring
// containing the origin (throws InvalidInput otherwise). The result is normalized (outer rings
// counterclockwise, holes clockwise); a ring of it may pass through one vertex twice where a
// hole touches its outer ring.
PolygonSet offset_by(const PolygonSet& x, const Ring& k, const CancelHook& cancel = {});

// (X^C ⊕ K)^C = {p : p - K ⊆ X}; for a centrally symmetric K (every D̄_{a,b}) that is
// {p : p + K ⊆ X}. Same conventions as offset_by; may be empty.
PolygonSet inset_by(const PolygonSet& x, const Ring& k, const CancelHook& cancel = {});

// inner ⊆ outer for two valid regions, exactly.
bool region_contains(const PolygonSet& outer, const PolygonSet& inner);

} // namespace penshape
