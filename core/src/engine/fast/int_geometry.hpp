#pragma once
// Integer-grid geometry for the fast engine. Every polygon the engine touches has integer
// vertices (grid units, |coordinate| <= 2^31, see grid_frame.hpp), so orientations and winding
// numbers are exact in 128-bit integers. Distances here are doubles that only propose: every
// distance comparison that decides a certificate is in certified.hpp.
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/distance_kernel.hpp"
#include "geometry/exact_predicates.hpp"

namespace penshape::fast {

// 128-bit products keep orientations of 2^31-bounded coordinates exact (the kernel's type).
using detail::Int128;

struct IPt {
  std::int64_t x = 0;
  std::int64_t y = 0;
  friend bool operator==(const IPt&, const IPt&) = default;
};

struct DPt {
  double x = 0.0;
  double y = 0.0;
};

// A closed ring (last vertex joins the first); the region is on the left of every edge, so
// outer rings are counterclockwise and holes clockwise (nonzero winding = 1 inside).
using IRing = std::vector<IPt>;
using IRings = std::vector<IRing>;

inline DPt to_d(IPt p) { return {static_cast<double>(p.x), static_cast<double>(p.y)}; }

// Exact orientation of c relative to the directed line a->b: >0 left, <0 right, 0 collinear.
// The kernel's integer instance (geometry/exact_predicates.hpp).
inline int orientation(IPt a, IPt b, IPt c) {
  return detail::exact_orientation(a.x, a.y, b.x, b.y, c.x, c.y);
}

// Lexicographic (x, then y) order: -1, 0 or +1 (the kernel's sweep orders its events by it).
inline int compare_lex(IPt p, IPt q) {
  if (p.x != q.x) return p.x < q.x ? -1 : 1;
  return p.y < q.y ? -1 : (p.y > q.y ? 1 : 0);
}

// Distance from p to the segment [a, b] (a may equal b): the shared kernel's double path
// (geometry/distance_kernel.hpp), for proposals only.
inline double point_segment_distance(DPt p, DPt a, DPt b) {
  return detail::proposed_distance(p, a, b);
}

// Twice the signed area, exactly.
Int128 twice_area(const IRing& ring);

// Drops repeated consecutive vertices and rings with fewer than three vertices or zero area
// (for Clipper's candidates; the rounded input keeps every ring, see remove_repeats).
void clean_rings(IRings& rings);

// Drops repeated consecutive vertices (and a last vertex equal to the first) and keeps every
// ring, even one that collapsed to a segment or a point: a ring thinner than a grid unit is
// still part of Q, and its edges must stay in Q̃ (README.md, "Input rounding").
void remove_repeats(IRings& rings);

} // namespace penshape::fast
