#pragma once
// Internal: inward shifts of a convex polygon's edge lines. Candidates are built in doubles;
// every answer that matters is then certified with exact rationals (convex_decide.cpp).
#include <vector>

#include "geometry/segment_distance.hpp"
#include "penshape/core/polygon_set.hpp"

namespace penshape::detail {

// a·x + b·y <= c, in doubles.
struct HalfPlaneD {
  double a = 0;
  double b = 0;
  double c = 0;
};

// The edge half-planes of a counterclockwise convex ring (outward normals (dy, -dx)), each
// shifted inward by `shift` (a distance; negative shifts outward).
std::vector<HalfPlaneD> shifted_edge_half_planes(const std::vector<PointD>& ring, double shift);

// The intersection of half-planes in counterclockwise angular order: vertex k is where the
// planes of edges k and k + 1 meet; edge_plane[k] is the index (into `planes`) of edge k's
// plane. Empty when it has no interior (as far as doubles can tell).
struct ConvexCut {
  std::vector<PointD> vertices;
  std::vector<std::size_t> edge_plane;
};
ConvexCut intersect_sorted_half_planes(const std::vector<HalfPlaneD>& planes);

// Exact: is the convex ring `pi` (its vertices taken as exact binary fractions) inside every
// edge half-plane of the exact convex ring `q` shifted inward by `shift` >= 0? Uses no square
// root: c - n·v >= shift·|n|  <=>  c - n·v >= 0 and (c - n·v)² >= shift²·|n|². Only the vertex of
// `pi` extreme in each normal direction is tested (after an exact convexity check), found with
// a pointer that turns with the edges: linear time.
bool convex_ring_inside_inset(const std::vector<PointD>& pi, const Ring& q, const Rational& shift);

} // namespace penshape::detail
