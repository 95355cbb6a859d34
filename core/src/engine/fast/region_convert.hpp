#pragma once
// Grid regions to exact polygon sets and back, through a GridFrame.
#include "clipper_stage.hpp"
#include "grid_frame.hpp"
#include "penshape/core/polygon_set.hpp"

namespace penshape::fast {

// Every vertex as the exact rational the grid point stands for.
PolygonSet to_polygon_set(const GridFrame& frame, const IRegion& region);
// Every vertex rounded to the grid (exact for a set that came from the same frame).
IRegion to_grid(const GridFrame& frame, const PolygonSet& set);

} // namespace penshape::fast
