#pragma once
// Corner seeds from the deconstruction's skeleton P: its few vertices are the corners of the
// intended shape the engine recovered, so the triangle and quadrilateral fits may start there.
#include <vector>

#include "recognize/fitting/fit.hpp"

namespace penshape::recognize_detail {

// The outer ring of P's largest polygon reduced to k vertices (repeatedly dropping the vertex
// nearest its neighbours' chord); empty when the ring has fewer than k vertices.
std::vector<PointD> skeleton_corners(const PolygonSet& skeleton, std::size_t k);

// For k = 3 and 4: a polygon fit started at the skeleton's corners replaces the family's fit in
// `fits` (and, for k = 4, the rectangle, square and diamond fits derived from it) when its fit
// error is lower; a family with no fit yet gets the seeded one.
void apply_skeleton_seeds(const PreparedStroke& s, const PolygonSet& skeleton,
                          std::vector<Fit>& fits);

} // namespace penshape::recognize_detail
