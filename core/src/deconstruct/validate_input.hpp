#pragma once
// A yes/no form of validate_region for callers that try candidates (the simplifier): the same
// O(n log n) checks (geometry/segment_sweep, geometry/ring_nesting), without a message; and the
// vertex limit alone (deconstruct() on a ValidatedRegion). Internal.
#include <cstddef>

#include "penshape/core/polygon_set.hpp"

namespace penshape::detail {

// True when validate_region would accept the set, with no vertex limit; an empty set is valid
// here (a candidate is never empty, and emptiness is the caller's question).
bool is_valid_region(const PolygonSet& set);

// validate_region's vertex limit alone, with its message (InvalidInput).
void check_vertex_limit(const PolygonSet& q, std::size_t max_vertices);

} // namespace penshape::detail
