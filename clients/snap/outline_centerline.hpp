#pragma once
// A filled calligraphy outline (Inkscape's Calligraphy tool: one closed path that runs along one
// edge of the stroke from its start, round the end, and back along the other edge) read back as
// a pen path and a pen radius.
//
// Radius: a stroke of centre-line length L drawn with a disk of radius r has area
// A = 2 r L + pi r^2 and perimeter P = 2 L + 2 pi r; eliminating L gives pi r^2 - P r + A = 0,
// whose smaller root is r. Centre line: the outline is cut at two vertices a and k into two
// chains from a to k; both are resampled by arc length and paired; the cut whose pairs are
// closest to 2r apart (least squares) wins (k searched with a at the outline's start, then a
// with that k), and the midpoints of its pairs, less r of arc length at each end (the caps), are
// the pen path.
#include <optional>
#include <vector>

#include "penshape/core/polygon_set.hpp" // PointD

namespace penshape::snap {

struct Centerline {
  std::vector<PointD> points;
  double radius = 0.0;
};

// nullopt when the outline is not a stroke's (fewer than 6 vertices, or a blob whose area and
// perimeter fit no stroke: P^2 < 4 pi A).
std::optional<Centerline> outline_centerline(const std::vector<PointD>& ring);

} // namespace penshape::snap
