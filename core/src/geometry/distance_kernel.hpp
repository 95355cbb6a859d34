#pragma once
// Point-to-segment distance, written once for every number type in the style of CGAL's traits:
// doubles propose, intervals (CGAL::Interval_nt, directed rounding) certify, exact rationals
// settle what an interval cannot. The engines' certificates compare distances only through
// compare_squared_distance, so their arithmetic is reviewed here. Internal to core.
//
// Interval_nt<false> needs the FPU rounding towards +infinity: compare_squared_distance sets it
// for its own duration (CGAL::Protect_FPU_rounding), so callers need not.
#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/gmpxx.h>

#include <optional>

#include "penshape/core/polygon_set.hpp"

namespace penshape::detail {

template <typename NT>
struct Point2 {
  NT x;
  NT y;
};

using IntervalNT = CGAL::Interval_nt<false>;
using IPoint = Point2<IntervalNT>;

// How each number type answers "is v certainly <= 0 / >= w": plain comparisons for totally
// ordered types, the interval bounds for intervals (false means "not certain").
inline bool certainly_nonpositive(double v) { return v <= 0; }
inline bool certainly_nonpositive(const Rational& v) { return sgn(v) <= 0; }
inline bool certainly_nonpositive(const IntervalNT& v) { return v.sup() <= 0; }
inline bool certainly_at_least(double v, double w) { return v >= w; }
inline bool certainly_at_least(const Rational& v, const Rational& w) { return v >= w; }
inline bool certainly_at_least(const IntervalNT& v, const IntervalNT& w) {
  return v.inf() >= w.sup();
}
inline bool certainly_between(double dot, double len2) { return dot > 0 && dot < len2; }
inline bool certainly_between(const Rational& dot, const Rational& len2) {
  return sgn(dot) > 0 && dot < len2;
}
inline bool certainly_between(const IntervalNT& dot, const IntervalNT& len2) {
  return dot.inf() > 0 && dot.sup() < len2.inf();
}

// d(p, [s, t])²: the nearest point is s, t or the foot of the perpendicular. nullopt only for
// intervals that cannot tell which (then the caller decides exactly).
template <typename NT>
std::optional<NT> squared_distance_to_segment(const Point2<NT>& p, const Point2<NT>& s,
                                              const Point2<NT>& t) {
  const NT dx = t.x - s.x;
  const NT dy = t.y - s.y;
  const NT px = p.x - s.x;
  const NT py = p.y - s.y;
  const NT proj = px * dx + py * dy;
  if (certainly_nonpositive(proj)) return NT(px * px + py * py);
  const NT len2 = dx * dx + dy * dy;
  if (certainly_at_least(proj, len2)) {
    const NT qx = p.x - t.x;
    const NT qy = p.y - t.y;
    return NT(qx * qx + qy * qy);
  }
  if (certainly_between(proj, len2)) {
    const NT cross = dx * py - dy * px;
    return NT(cross * cross / len2);
  }
  return std::nullopt;
}

inline IPoint enclose(const ExactPoint& p) {
  return {IntervalNT(CGAL::to_interval(p.x)), IntervalNT(CGAL::to_interval(p.y))};
}
inline IntervalNT enclose(const Rational& v) { return IntervalNT(CGAL::to_interval(v)); }

// sign(d(p, [s, t])² - r2), certified: intervals first (points enclosed once by the caller),
// exact rationals when they cannot decide.
inline int compare_squared_distance(const ExactPoint& p, const IPoint& pi, const ExactPoint& s,
                                    const IPoint& si, const ExactPoint& t, const IPoint& ti,
                                    const Rational& r2, const IntervalNT& r2i) {
  {
    const CGAL::Protect_FPU_rounding<true> rounding;
    if (const auto d2 = squared_distance_to_segment(pi, si, ti)) {
      if (d2->sup() < r2i.inf()) return -1;
      if (d2->inf() > r2i.sup()) return 1;
    }
  }
  const Point2<Rational> pe{p.x, p.y}, se{s.x, s.y}, te{t.x, t.y};
  const int c = cmp(*squared_distance_to_segment(pe, se, te), r2);
  return (c > 0) - (c < 0);
}

} // namespace penshape::detail
