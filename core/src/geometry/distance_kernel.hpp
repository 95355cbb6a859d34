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

#include <algorithm>
#include <cmath>
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

// The double instance for any point type with double x and y (PointD, the fast engine's DPt):
// proposals only, never a certificate. The one place a proposal's distance is written.
template <typename P>
double proposed_squared_distance(const P& p, const P& s, const P& t) {
  using D = Point2<double>;
  // Doubles always decide a branch: the optional is never empty.
  return *squared_distance_to_segment(D{p.x, p.y}, D{s.x, s.y}, D{t.x, t.y});
}
template <typename P>
double proposed_distance(const P& p, const P& s, const P& t) {
  return std::sqrt(proposed_squared_distance(p, s, t));
}
// The parameter u in [0, 1] of the point s + u (t - s) nearest p (0 when s == t), in doubles:
// for callers that need the foot point itself, not only its distance.
// The same from r = p - s, d = t - s and len2 = |d|², for callers that keep them.
template <typename V>
double proposed_foot_parameter_along(const V& r, const V& d, double len2) {
  if (!(len2 > 0)) return 0.0;
  return std::clamp((r.x * d.x + r.y * d.y) / len2, 0.0, 1.0);
}
template <typename P>
double proposed_foot_parameter(const P& p, const P& s, const P& t) {
  const Point2<double> d{t.x - s.x, t.y - s.y};
  return proposed_foot_parameter_along(Point2<double>{p.x - s.x, p.y - s.y}, d,
                                       d.x * d.x + d.y * d.y);
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

// ---- Certified upper bounds (the recognizer's snap certificates) ----
// A certificate's bound is a maximum of distances, each bounded above through a part of the other
// side that doubles proposed (the nearest segment, the foot point on a curve): any part gives an
// upper bound, so a poor proposal only loosens the bound, never breaks it. These evaluate with
// Interval_nt<false>, so the caller holds a CGAL::Protect_FPU_rounding<true> guard.
namespace penshape::detail {

inline IPoint enclose(PointD p) { return {IntervalNT(p.x), IntervalNT(p.y)}; }

// Encloses d(p, [s, t])² for every p in the box: the exact case where certain, else the distance
// to the segment's line below and to its nearer end above.
inline IntervalNT squared_distance_enclosure(const IPoint& p, const IPoint& s, const IPoint& t) {
  if (const auto d2 = squared_distance_to_segment(p, s, t)) return *d2;
  const IntervalNT dx = t.x - s.x, dy = t.y - s.y;
  const IntervalNT to_s = CGAL::square(p.x - s.x) + CGAL::square(p.y - s.y);
  const IntervalNT to_t = CGAL::square(p.x - t.x) + CGAL::square(p.y - t.y);
  const IntervalNT len2 = CGAL::square(dx) + CGAL::square(dy);
  const double line =
      len2.inf() > 0 ? (CGAL::square(dx * (p.y - s.y) - dy * (p.x - s.x)) / len2).inf() : 0.0;
  return {std::max(0.0, line), std::min(to_s.sup(), to_t.sup())};
}

// >= d(p, [s, t]) for every p in the box.
inline double distance_upper(const IPoint& p, const IPoint& s, const IPoint& t) {
  return CGAL::sqrt(squared_distance_enclosure(p, s, t)).sup();
}
inline double distance_upper(const IPoint& p, PointD s, PointD t) {
  return distance_upper(p, enclose(s), enclose(t));
}
// >= |p - q| for every p, q in the boxes.
inline double distance_upper(const IPoint& p, const IPoint& q) {
  return CGAL::sqrt(CGAL::square(p.x - q.x) + CGAL::square(p.y - q.y)).sup();
}

// cos and sin enclosed: the C library's result widened by two ulps each side (glibc documents at
// most 1 ulp for both on x86-64 and aarch64). Call these in the default rounding mode (outside
// the guard): the library's accuracy is stated for it.
inline IntervalNT widen_ulps(double v) {
  const double lo = std::nextafter(std::nextafter(v, -HUGE_VAL), -HUGE_VAL);
  const double hi = std::nextafter(std::nextafter(v, HUGE_VAL), HUGE_VAL);
  return {std::max(-1.0, lo), std::min(1.0, hi)};
}
inline IntervalNT enclose_cos(double t) { return widen_ulps(std::cos(t)); }
inline IntervalNT enclose_sin(double t) { return widen_ulps(std::sin(t)); }

} // namespace penshape::detail
