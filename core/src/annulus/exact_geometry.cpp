#include "exact_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace penshape::annulus::detail {

int orientation(PointD a, PointD b, PointD c) {
  const double l = (b.x - a.x) * (c.y - a.y);
  const double r = (b.y - a.y) * (c.x - a.x);
  const double det = l - r;
  // Shewchuk's bound for the fast orientation test is (3 + 16 eps) eps (|l| + |r|); 1e-15 is
  // more than twice that.
  const double bound = 1e-15 * (std::abs(l) + std::abs(r));
  if (det > bound) return 1;
  if (det < -bound) return -1;
  const ExactPoint A = exact(a);
  const ExactPoint B = exact(b);
  const ExactPoint C = exact(c);
  const Rational e = (B.x - A.x) * (C.y - A.y) - (B.y - A.y) * (C.x - A.x);
  return sgn(e);
}

namespace {
// c is collinear with ab: is it inside the closed box of ab?
bool on_segment(PointD a, PointD b, PointD c) {
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}
} // namespace

bool segments_intersect(PointD a, PointD b, PointD c, PointD d) {
  if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
      std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y)) {
    return false;
  }
  const int o1 = orientation(a, b, c);
  const int o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a);
  const int o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0) {
    if (o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0) return true;
  }
  if (o1 == 0 && on_segment(a, b, c)) return true;
  if (o2 == 0 && on_segment(a, b, d)) return true;
  if (o3 == 0 && on_segment(c, d, a)) return true;
  if (o4 == 0 && on_segment(c, d, b)) return true;
  return o1 * o2 < 0 && o3 * o4 < 0;
}

} // namespace penshape::annulus::detail
