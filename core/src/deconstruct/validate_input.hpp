#pragma once
// A yes/no form of validate_region for callers that try candidates (the simplifier): the same
// O(n log n) checks (geometry/segment_sweep, geometry/ring_nesting), without a message. Internal.
#include "penshape/core/polygon_set.hpp"

namespace penshape::detail {

// True when validate_region would accept the set, with no vertex limit; an empty set is valid
// here (a candidate is never empty, and emptiness is the caller's question).
bool is_valid_region(const PolygonSet& set);

} // namespace penshape::detail
