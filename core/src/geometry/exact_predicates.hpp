#pragma once
// The kernel's orientation and segment-intersection predicates, written once for every point
// type core uses: exact doubles (PointD), rationals with their nearest doubles (FilteredPoint),
// rationals alone (ExactPoint) and 64-bit integer points (the fast engine's grid). One
// floating-point filter with one derived error bound decides most calls; only near-degenerate
// ones pay for GMP arithmetic. Internal to core.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "geometry/exact_double.hpp"
#include "penshape/core/polygon_set.hpp"

namespace penshape::detail {

// Where the filter's doubles come from: the inputs themselves (exact), or each the double
// truncated from a rational (mpq_get_d: |x - x~| <= 2u|x~| for u = 2^-53).
enum class FilterInputs { kExact, kRounded };

// The sign of D = (b - a) × (c - a) from doubles, or nullopt when the doubles cannot tell.
// det = l - r with l = (bx - ax)(cy - ay) and r = (by - ay)(cx - ax), evaluated in doubles.
// - Rounding of the differences, products and subtraction: Shewchuk's orient2d bound
//   (3 + 16u)u(|l| + |r|); 4u(|l| + |r|) also covers the rounding of the bound's own sum.
// - Rounded inputs: with M the largest |coordinate|, every true difference is within 4uM of the
//   doubles' one (of size <= 2M), so each true product is within 16uM² + 16u²M² of it and D
//   within 32uM² + 32u²M² of the doubles' determinant; 36uM² covers that and its rounding. This
//   needs normal coordinates' error bounds, so rounded inputs decide only for M > 1e-100.
// - Underflow: a product below the normal range is off by at most half the smallest subnormal;
//   eight of them cover both products and the bound's own underflow.
// NaN or infinity (overflow) makes every comparison false: undecided.
inline std::optional<int> orientation_filter(double ax, double ay, double bx, double by, double cx,
                                             double cy, FilterInputs inputs) {
  constexpr double u = std::numeric_limits<double>::epsilon() / 2;
  const double l = (bx - ax) * (cy - ay);
  const double r = (by - ay) * (cx - ax);
  const double det = l - r;
  double bound =
      4 * u * (std::abs(l) + std::abs(r)) + 8 * std::numeric_limits<double>::denorm_min();
  if (inputs == FilterInputs::kRounded) {
    const double m = std::max(
        {std::abs(ax), std::abs(ay), std::abs(bx), std::abs(by), std::abs(cx), std::abs(cy)});
    if (!(m > 1e-100)) return std::nullopt;
    bound += 36 * u * m * m;
  }
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return std::nullopt;
}

// (b - a) × (c - a) in any number type: doubles propose, CGAL intervals enclose it (the caller
// holds the rounding guard), rationals give it exactly.
template <typename NT>
NT orientation_determinant(const NT& ax, const NT& ay, const NT& bx, const NT& by, const NT& cx,
                           const NT& cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

// The integer instance (the fast engine's grid points): for |coordinate| < 2^62 the differences
// fit in 64 bits and their products in 128, so the determinant is exact.
__extension__ typedef __int128 Int128;
inline Int128 orientation_determinant(std::int64_t ax, std::int64_t ay, std::int64_t bx,
                                      std::int64_t by, std::int64_t cx, std::int64_t cy) {
  return static_cast<Int128>(bx - ax) * (cy - ay) - static_cast<Int128>(by - ay) * (cx - ax);
}

// Its sign for an exact number type (Rational, or 64-bit integers through the instance above):
// +1 left, -1 right, 0 collinear.
template <typename NT>
int exact_orientation(const NT& ax, const NT& ay, const NT& bx, const NT& by, const NT& cx,
                      const NT& cy) {
  const auto det = orientation_determinant(ax, ay, bx, by, cx, cy);
  return static_cast<int>(det > 0) - static_cast<int>(det < 0);
}

// A rational point with its double (truncated), converted once. When `is_double` the doubles
// are the point exactly (grid and file coordinates nearly always are): predicates then decide on
// them with the exact inputs' error bound, and equal doubles are equal coordinates (no GMP).
struct FilteredPoint {
  const ExactPoint* exact = nullptr;
  double x = 0.0;
  double y = 0.0;
  bool is_double = false;
};

inline FilteredPoint filtered(const ExactPoint& p) {
  bool exact_x = false;
  bool exact_y = false;
  const double x = to_double_checked(p.x, exact_x);
  const double y = to_double_checked(p.y, exact_y);
  return {&p, x, y, exact_x && exact_y};
}

// Lexicographic (x, then y) order of points, exact: -1, 0 or +1. The same vertex first (one
// vertex seen from its two edges), then doubles (rounding is monotone, so distinct doubles
// decide), and the rationals on a tie unless the doubles are the points.
inline int compare_lex(const FilteredPoint& p, const FilteredPoint& q) {
  if (p.exact == q.exact) return 0;
  if (p.x != q.x) return p.x < q.x ? -1 : 1;
  if (!(p.is_double && q.is_double) && p.exact->x != q.exact->x) {
    return p.exact->x < q.exact->x ? -1 : 1;
  }
  if (p.y != q.y) return p.y < q.y ? -1 : 1;
  if ((p.is_double && q.is_double) || p.exact->y == q.exact->y) return 0;
  return p.exact->y < q.exact->y ? -1 : 1;
}

// +1 left turn a → b → c, -1 right turn, 0 collinear. Exact for every point type.
inline int orientation(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  return exact_orientation(a.x, a.y, b.x, b.y, c.x, c.y);
}
inline int orientation(const FilteredPoint& a, const FilteredPoint& b, const FilteredPoint& c) {
  const FilterInputs inputs =
      a.is_double && b.is_double && c.is_double ? FilterInputs::kExact : FilterInputs::kRounded;
  if (const auto s = orientation_filter(a.x, a.y, b.x, b.y, c.x, c.y, inputs)) {
    return *s;
  }
  return orientation(*a.exact, *b.exact, *c.exact);
}
inline int orientation(PointD a, PointD b, PointD c) {
  if (const auto s = orientation_filter(a.x, a.y, b.x, b.y, c.x, c.y, FilterInputs::kExact)) {
    return *s;
  }
  return orientation(exact(a), exact(b), exact(c));
}

// The exact coordinates behind each point type: the point itself, but a FilteredPoint's rational.
template <typename P>
const P& exact_coordinates(const P& p) {
  return p;
}
inline const ExactPoint& exact_coordinates(const FilteredPoint& p) { return *p.exact; }

// c lies on the closed segment ab, given that a, b, c are collinear.
template <typename P>
bool on_collinear_segment(const P& a, const P& b, const P& c) {
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

// The bounding boxes of ab and cd are apart. On a FilteredPoint's doubles this is still exact:
// rounding is monotone, so a strict order of the doubles is the rationals' order.
template <typename P>
bool boxes_apart(const P& a, const P& b, const P& c, const P& d) {
  return std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
         std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y);
}

// Segments ab and cd cross at one point inside both (touching and overlapping do not count).
template <typename P>
bool segments_cross_properly(const P& a, const P& b, const P& c, const P& d) {
  return orientation(a, b, c) * orientation(a, b, d) < 0 &&
         orientation(c, d, a) * orientation(c, d, b) < 0;
}

// Closed segments ab and cd share at least one point. Exact.
template <typename P>
bool segments_intersect(const P& a, const P& b, const P& c, const P& d) {
  if (boxes_apart(a, b, c, d)) return false;
  const int o1 = orientation(a, b, c);
  const int o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a);
  const int o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true; // proper crossing
  const auto& ea = exact_coordinates(a);
  const auto& eb = exact_coordinates(b);
  const auto& ec = exact_coordinates(c);
  const auto& ed = exact_coordinates(d);
  return (o1 == 0 && on_collinear_segment(ea, eb, ec)) ||
         (o2 == 0 && on_collinear_segment(ea, eb, ed)) ||
         (o3 == 0 && on_collinear_segment(ec, ed, ea)) ||
         (o4 == 0 && on_collinear_segment(ec, ed, eb));
}

} // namespace penshape::detail
