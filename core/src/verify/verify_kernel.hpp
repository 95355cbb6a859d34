#pragma once
// The verifier's own arithmetic (penshape verify): rational points carried with their interval
// enclosures. Every predicate is decided by interval arithmetic with directed rounding (CGAL's
// Interval_nt) when the interval is conclusive and by exact GMP rationals otherwise, so no
// tolerance decides anything. Written apart from the engines on purpose: a verifier that shared
// their arithmetic would share their mistakes. Internal to core/src/verify.
#include <CGAL/Interval_nt.h>
#include <CGAL/gmpxx.h>

#include "penshape/core/polygon_set.hpp"

namespace penshape::verify {

// Callers hold a CGAL::Protect_FPU_rounding<true> guard (rounding towards +infinity), which
// Interval_nt<false> assumes.
using Interval = CGAL::Interval_nt<false>;

inline Interval enclose(const Rational& v) { return Interval(CGAL::to_interval(v)); }

// A rational point and its enclosure.
struct VPoint {
  ExactPoint e;
  Interval x;
  Interval y;
};

inline VPoint vpoint(ExactPoint p) {
  VPoint v{std::move(p), 0.0, 0.0};
  v.x = enclose(v.e.x);
  v.y = enclose(v.e.y);
  return v;
}

// A threshold L >= 0 for distance comparisons, with L² exact and enclosed.
struct Threshold {
  Rational value;
  Rational square;
  Interval square_iv;
  double approx = 0.0; // for choosing grid cells (padded by the index)
};
Threshold threshold(const Rational& l);

// sign(d(c, [a, b])² - l²): -1 nearer than l, 0 at l, +1 farther.
int compare_distance(const VPoint& c, const VPoint& a, const VPoint& b, const Threshold& l);

// Sign of (b - a) × (c - a): +1 left turn, -1 right turn, 0 collinear.
int orientation(const VPoint& a, const VPoint& b, const VPoint& c);

// sign(u - v), exactly.
int compare(const Rational& u, const Interval& ui, const Rational& v, const Interval& vi);

// Does the edge (a, b) cross the ray from p towards +x? The step of the even-odd rule (p not on
// the edge; an edge's lower end counts as below p, so a vertex on the ray is counted once).
bool crosses_ray(const VPoint& a, const VPoint& b, const VPoint& p);

// Do the closed segments [a, b] and [c, d] share a point?
bool segments_meet(const VPoint& a, const VPoint& b, const VPoint& c, const VPoint& d);

} // namespace penshape::verify
