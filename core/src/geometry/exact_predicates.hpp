#pragma once
// Exact orientation and segment predicates on rational points, with a floating-point filter:
// most calls decide from doubles, and only near-degenerate ones pay for GMP arithmetic. Internal.
#include <cmath>

#include "penshape/core/polygon_set.hpp"

namespace penshape::detail {

// A rational point with its nearest double, converted once.
struct FilteredPoint {
  const ExactPoint* exact = nullptr;
  double x = 0.0;
  double y = 0.0;
};

inline FilteredPoint filtered(const ExactPoint& p) { return {&p, p.x.get_d(), p.y.get_d()}; }

// Sign of the cross product (b - a) × (c - a): +1 left turn, -1 right turn, 0 collinear.
inline int orientation(const FilteredPoint& a, const FilteredPoint& b, const FilteredPoint& c) {
  const double det = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  // Each coordinate carries a relative error <= 2^-53 from the conversion, and the few
  // operations above add a handful more; 1e-12 · M² bounds the total with a wide margin.
  const double m = std::max(
      {std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y), std::abs(c.x), std::abs(c.y)});
  const double bound = 1e-12 * m * m;
  // Only where products stay normal doubles (tiny coordinates fall through to exact).
  if (m > 1e-100) {
    if (det > bound) return 1;
    if (det < -bound) return -1;
  }
  const ExactPoint& pa = *a.exact;
  const ExactPoint& pb = *b.exact;
  const ExactPoint& pc = *c.exact;
  const Rational exact_det = (pb.x - pa.x) * (pc.y - pa.y) - (pb.y - pa.y) * (pc.x - pa.x);
  return sgn(exact_det);
}

// c lies on the closed segment ab, given that a, b, c are collinear.
inline bool on_collinear_segment(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

// Closed segments ab and cd share at least one point.
inline bool segments_intersect(const FilteredPoint& a, const FilteredPoint& b,
                               const FilteredPoint& c, const FilteredPoint& d) {
  const int o1 = orientation(a, b, c);
  const int o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a);
  const int o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true; // proper crossing
  if (o1 == 0 && on_collinear_segment(*a.exact, *b.exact, *c.exact)) return true;
  if (o2 == 0 && on_collinear_segment(*a.exact, *b.exact, *d.exact)) return true;
  if (o3 == 0 && on_collinear_segment(*c.exact, *d.exact, *a.exact)) return true;
  if (o4 == 0 && on_collinear_segment(*c.exact, *d.exact, *b.exact)) return true;
  return false;
}

} // namespace penshape::detail
