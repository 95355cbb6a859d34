#pragma once
// Distance bounds between a box (an interval point: one grid point, or a block of them) and a
// segment, for the ink certificate's pruned grid scan (ink_certificate.cpp). Unlike
// distance_kernel.hpp's enclosure, whose branch can change with the box's width, each bound here
// is MONOTONE in the box: for boxes b ⊆ B, lower(b) >= lower(B) and upper(b) <= upper(B), as
// computed (directed rounding included). Every term is an interval expression in the box, which
// CGAL's Interval_nt evaluates inclusion-monotonically, and a term is used only under a
// condition that is certain for B, hence for b. So a block whose bound proves "every point is
// out" or "no point exceeds m" proves it for the values the scan computes at its points, bit for
// bit, not only for the true distances. Callers hold the rounding guard (upward rounding).
#include <algorithm>

#include "geometry/distance_kernel.hpp"
#include "recognize/fitting/geometry.hpp"

namespace penshape::recognize_detail {

// Lower and upper bounds on d(x, [s, t])^2 over every x in the box.
struct BoxSegmentSquared {
  double lower;
  double upper;
};

inline BoxSegmentSquared box_segment_squared(const detail::IPoint& p, PointD a, PointD b) {
  using detail::IntervalNT;
  const IntervalNT sx(a.x), sy(a.y), tx(b.x), ty(b.y);
  const IntervalNT to_s = CGAL::square(p.x - sx) + CGAL::square(p.y - sy);
  if (a.x == b.x && a.y == b.y) return {to_s.inf(), to_s.sup()};
  const IntervalNT to_t = CGAL::square(p.x - tx) + CGAL::square(p.y - ty);
  const IntervalNT dx = tx - sx, dy = ty - sy;
  const IntervalNT len2 = CGAL::square(dx) + CGAL::square(dy);
  // The line's distance bounds the segment's from below; it is the segment's distance when the
  // foot certainly falls on it. Past an end (certainly), the end's distance is the distance.
  const IntervalNT line = CGAL::square(dx * (p.y - sy) - dy * (p.x - sx)) / len2;
  const IntervalNT along_s = (p.x - sx) * dx + (p.y - sy) * dy;
  const IntervalNT along_t = (tx - p.x) * dx + (ty - p.y) * dy;
  double lower = std::max(0.0, line.inf());
  double upper = std::min(to_s.sup(), to_t.sup());
  if (along_s.sup() < 0) lower = std::max(lower, to_s.inf());
  if (along_t.sup() < 0) lower = std::max(lower, to_t.inf());
  if (along_s.inf() >= 0 && along_t.inf() >= 0) upper = std::min(upper, line.sup());
  return {lower, upper};
}

// >= d(x, [a, b]) for every x in the box (monotone in the box).
inline double box_segment_upper(const detail::IPoint& p, PointD a, PointD b) {
  return CGAL::sqrt(detail::IntervalNT(box_segment_squared(p, a, b).upper)).sup();
}

// [box - radius, box + radius] with each bound one ulp outward (nondecreasing in the box's
// bounds, in any rounding mode): the query box of a segment grid.
inline detail::GridBox grown_box(const detail::IPoint& p, double radius) {
  const double inf = HUGE_VAL;
  return {std::nextafter(p.x.inf() - radius, -inf), std::nextafter(p.y.inf() - radius, -inf),
          std::nextafter(p.x.sup() + radius, inf), std::nextafter(p.y.sup() + radius, inf)};
}

// False only when every segment of the index is farther than radius from every point of the box
// (monotone: a box inside a box for which it is false gives false). The grid lists every segment
// whose box meets the query box; a larger box lists a superset.
inline bool index_maybe_within(const SegmentIndex& index, const detail::IPoint& p, double radius) {
  const detail::GridBox query = grown_box(p, radius);
  const double r2 = CGAL::square(detail::IntervalNT(radius)).sup();
  return index.visit_near(query, [&](std::size_t s) {
    return box_segment_squared(p, index.segment(s).a, index.segment(s).b).lower <= r2;
  });
}

// box_segment_upper(box, s) for the double-nearest segment s to `near`: >= index_upper(b, .)
// for every box b inside this one (a bound for blocks, cheaper than the least one).
inline double nearest_segment_upper(const SegmentIndex& index, const detail::IPoint& p,
                                    PointD near) {
  std::uint32_t id = 0;
  (void)index.nearest_above(near, 0.0, id);
  return box_segment_upper(p, index.segment(id).a, index.segment(id).b);
}

// min over every segment of the index of box_segment_upper(box, segment), exactly (the value
// does not depend on the proposal): the double-nearest segment to `near` proposes u0, and only
// segments whose box meets the box grown by u0 can give less (the others are farther than u0
// from every point of it, and the upper bound exceeds the distance). Monotone in the box.
inline double index_upper(const SegmentIndex& index, const detail::IPoint& p, PointD near) {
  double best = nearest_segment_upper(index, p, near);
  (void)index.visit_near(grown_box(p, best), [&](std::size_t s) {
    best = std::min(best, box_segment_upper(p, index.segment(s).a, index.segment(s).b));
    return false;
  });
  return best;
}

} // namespace penshape::recognize_detail
