#pragma once
// Which ring directly contains which, for rings whose boundaries are pairwise disjoint (input
// validation establishes that first): one sweep in O(n log n) with exact predicates, instead of
// a point-in-polygon test of every ring against every other. Internal to core.
#include <cstddef>
#include <vector>

#include "geometry/exact_predicates.hpp"

namespace penshape::detail {

// rings[k] are the vertices of ring k (at least 3, no repeated consecutive vertices, nonzero
// area, boundaries pairwise disjoint). Returns parent[k]: the innermost other ring whose
// interior contains ring k, or -1.
std::vector<long> ring_parents(const std::vector<std::vector<FilteredPoint>>& rings);

} // namespace penshape::detail
