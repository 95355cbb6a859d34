// The verifier's predicates: interval filter first, exact rationals when it cannot decide.
#include "verify/verify_kernel.hpp"

#include <optional>

namespace penshape::verify {
namespace {

// d(c, [a, b])² exactly: the nearest point is a, b or the foot of the perpendicular.
Rational exact_squared_distance(const ExactPoint& c, const ExactPoint& a, const ExactPoint& b) {
  const Rational ux = b.x - a.x;
  const Rational uy = b.y - a.y;
  const Rational wx = c.x - a.x;
  const Rational wy = c.y - a.y;
  const Rational dot = wx * ux + wy * uy;
  if (sgn(dot) <= 0) return wx * wx + wy * wy;
  const Rational len2 = ux * ux + uy * uy;
  if (dot >= len2) {
    const Rational vx = c.x - b.x;
    const Rational vy = c.y - b.y;
    return vx * vx + vy * vy;
  }
  const Rational cross = ux * wy - uy * wx;
  return cross * cross / len2;
}

// The same in intervals; nullopt when the case (which nearest point) is not certain.
std::optional<Interval> interval_squared_distance(const VPoint& c, const VPoint& a,
                                                  const VPoint& b) {
  const Interval ux = b.x - a.x;
  const Interval uy = b.y - a.y;
  const Interval wx = c.x - a.x;
  const Interval wy = c.y - a.y;
  const Interval dot = wx * ux + wy * uy;
  if (dot.sup() <= 0) return wx * wx + wy * wy;
  const Interval len2 = ux * ux + uy * uy;
  if (dot.inf() >= len2.sup()) {
    const Interval vx = c.x - b.x;
    const Interval vy = c.y - b.y;
    return vx * vx + vy * vy;
  }
  if (dot.inf() > 0 && dot.sup() < len2.inf()) {
    const Interval cross = ux * wy - uy * wx;
    return CGAL::square(cross) / len2;
  }
  return std::nullopt;
}

} // namespace

Threshold threshold(const Rational& l) {
  Threshold t{l, l * l, 0.0, l.get_d()};
  t.square_iv = enclose(t.square);
  return t;
}

int compare_distance(const VPoint& c, const VPoint& a, const VPoint& b, const Threshold& l) {
  if (const auto d2 = interval_squared_distance(c, a, b)) {
    if (d2->sup() < l.square_iv.inf()) return -1;
    if (d2->inf() > l.square_iv.sup()) return 1;
  }
  const int s = cmp(exact_squared_distance(c.e, a.e, b.e), l.square);
  return (s > 0) - (s < 0);
}

int orientation(const VPoint& a, const VPoint& b, const VPoint& c) {
  const Interval det = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (det.inf() > 0) return 1;
  if (det.sup() < 0) return -1;
  return sgn((b.e.x - a.e.x) * (c.e.y - a.e.y) - (b.e.y - a.e.y) * (c.e.x - a.e.x));
}

bool crosses_ray(const VPoint& a, const VPoint& b, const VPoint& p) {
  const bool a_below = compare(a.e.y, a.y, p.e.y, p.y) <= 0;
  const bool b_below = compare(b.e.y, b.y, p.e.y, p.y) <= 0;
  if (a_below == b_below) return false;
  const int o = orientation(a, b, p);
  return (a_below && o > 0) || (!a_below && o < 0);
}

int compare(const Rational& u, const Interval& ui, const Rational& v, const Interval& vi) {
  if (ui.sup() < vi.inf()) return -1;
  if (ui.inf() > vi.sup()) return 1;
  const int c = cmp(u, v);
  return c < 0 ? -1 : (c > 0 ? 1 : 0);
}

namespace {
// c on the closed segment [a, b], given a, b, c collinear.
bool within_box(const VPoint& a, const VPoint& b, const VPoint& c) {
  auto between = [](const Rational& lo, const Rational& hi, const Rational& v) {
    return (lo <= v && v <= hi) || (hi <= v && v <= lo);
  };
  return between(a.e.x, b.e.x, c.e.x) && between(a.e.y, b.e.y, c.e.y);
}
} // namespace

bool segments_meet(const VPoint& a, const VPoint& b, const VPoint& c, const VPoint& d) {
  const int o1 = orientation(a, b, c);
  const int o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a);
  const int o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  if (o1 == 0 && within_box(a, b, c)) return true;
  if (o2 == 0 && within_box(a, b, d)) return true;
  if (o3 == 0 && within_box(c, d, a)) return true;
  if (o4 == 0 && within_box(c, d, b)) return true;
  return false;
}

} // namespace penshape::verify
