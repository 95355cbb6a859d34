#pragma once
// Small double-precision plane geometry shared by the recognizer's fitters and its certificate.
// Point arithmetic is the public penshape/core/point_arithmetic.hpp and point-to-segment
// distance the kernel's (geometry/distance_kernel.hpp), not copies.
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "geometry/distance_kernel.hpp"
#include "geometry/segment_grid.hpp"
#include "penshape/core/point_arithmetic.hpp"
#include "penshape/core/polygon_set.hpp"

namespace penshape::recognize_detail {

// Squared distance from p to the segment [a, b] (a == b allowed): the one kernel's double
// instance (geometry/distance_kernel.hpp), which proposes; certificates evaluate the same formula
// in intervals (certified_distance.hpp).
inline double segment_distance2(PointD p, PointD a, PointD b) {
  return detail::proposed_squared_distance(p, a, b);
}
inline double segment_distance(PointD p, PointD a, PointD b) {
  return std::sqrt(segment_distance2(p, a, b));
}

// A segment of double points, and the one segment grid (geometry/segment_grid.hpp) over them:
// the ink certificate's index over the ink polygon's edges and a sampled ellipse, the path
// certificates' over the stroke.
struct Segment {
  PointD a;
  PointD b;
};
using SegmentIndex = detail::SegmentGrid<Segment>;

// Distance from p to the polyline through `path` (one point: distance to it).
inline double polyline_distance(PointD p, std::span<const PointD> path) {
  if (path.size() == 1) return distance(p, path[0]);
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    best = std::min(best, segment_distance2(p, path[i], path[i + 1]));
  }
  return std::sqrt(best);
}

// Intersection of the lines p + s u and q + t v; false when (nearly) parallel.
inline bool line_intersection(PointD p, PointD u, PointD q, PointD v, PointD& out) {
  const double d = cross(u, v);
  if (std::abs(d) < 1e-9 * norm(u) * norm(v)) return false;
  const double s = cross(q - p, v) / d;
  out = p + s * u;
  return true;
}

inline double path_length(std::span<const PointD> path) {
  double len = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) len += distance(path[i], path[i + 1]);
  return len;
}

// Points along `path` with arc-length spacing exactly length / (count - 1), both ends kept.
std::vector<PointD> resample(std::span<const PointD> path, std::size_t count);

// A closed path (first point repeated at the end) from a ring of corners.
inline std::vector<PointD> closed_ring(const std::vector<PointD>& corners) {
  std::vector<PointD> ring = corners;
  if (!ring.empty()) ring.push_back(ring.front());
  return ring;
}

} // namespace penshape::recognize_detail
