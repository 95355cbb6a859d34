#pragma once
// Is a claimed solution P a valid region? Exact (the verifier's own predicates). Internal.
#include <optional>
#include <string>

#include "penshape/core/polygon_set.hpp"

namespace penshape::verify {

// nullopt when valid, else what is wrong and where ("polygon 2, hole 1, vertex 7: ...").
// Valid: every ring has distinct consecutive vertices; a ring of non-zero area has >= 3
// vertices, is simple, and its adjacent edges do not fold back; a ring of zero area (an open
// polyline traced back and forth, as simplified solutions use) may fold on itself; no two rings
// meet; every hole has non-zero area and lies inside its outer ring and outside its siblings; an
// outer ring of non-zero area lies outside the other polygons.
std::optional<std::string> region_problem(const PolygonSet& set);

} // namespace penshape::verify
