// Clean shapes as exact polylines with a derived deviation (see verify_shape.hpp).
#include "verify/verify_shape.hpp"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace penshape::verify {
namespace {

// Self-protecting intervals: sin and cos are called between operations in the default rounding.
using I = CGAL::Interval_nt<true>;

constexpr std::size_t kMaxChords = 200'000;

double up(const I& v) { return v.sup(); }

// cos t and sin t enclosed: the library's result widened by two ulps each side.
I widen(double v) {
  const double lo = std::nextafter(std::nextafter(v, -INFINITY), -INFINITY);
  const double hi = std::nextafter(std::nextafter(v, INFINITY), INFINITY);
  return I(std::max(-1.0, lo), std::min(1.0, hi));
}
I icos(double t) { return widen(std::cos(t)); }
I isin(double t) { return widen(std::sin(t)); }

struct IPoint {
  I x;
  I y;
};

// The box's centre as a double point, and the box's reach from it (rounded up).
PointD centre_of(const IPoint& p, double& reach) {
  const PointD v{0.5 * (p.x.inf() + p.x.sup()), 0.5 * (p.y.inf() + p.y.sup())};
  const I dx = CGAL::max(I(p.x.sup()) - I(v.x), I(v.x) - I(p.x.inf()));
  const I dy = CGAL::max(I(p.y.sup()) - I(v.y), I(v.y) - I(p.y.inf()));
  reach = std::max(reach, up(CGAL::sqrt(dx * dx + dy * dy)));
  return v;
}

// |p - q| rounded up, q exact.
double reach_to(const IPoint& p, PointD q) {
  const I dx = p.x - I(q.x), dy = p.y - I(q.y);
  return up(CGAL::sqrt(CGAL::square(dx) + CGAL::square(dy)));
}

// P(t) = c + rot (a cos t, b sin t): an ellipse (a circle when a == b, rot the identity).
struct Curve {
  IPoint c;
  I a, b;
  I cos_r = I(1.0), sin_r = I(0.0);

  [[nodiscard]] IPoint at(double t) const {
    const I ex = a * icos(t), ey = b * isin(t);
    return {c.x + cos_r * ex - sin_r * ey, c.y + sin_r * ex + cos_r * ey};
  }
  [[nodiscard]] double bend() const { return up(CGAL::max(a, b)); } // >= |P''| and |P'|
};

// The chord polyline of P over [t0, t_end] (t_end enclosed by `end`: the polyline stops at its
// bound nearer t0, the rest of the curve is at most bend * width away along it). Returns sigma
// for this piece; the end vertices are `first` / `last` when given (their distance to the
// curve's ends counted by the caller).
double chords(const Curve& p, double t0, const I& end, double target, std::vector<PointD>& out) {
  const bool forward = end.inf() >= t0;
  const double t1 = forward ? end.inf() : end.sup();
  const double span = std::abs(t1 - t0);
  const double m = p.bend();
  auto n = static_cast<std::size_t>(std::ceil(span * std::sqrt(m / (8.0 * target))));
  n = std::clamp<std::size_t>(n, 8, kMaxChords);
  double reach = 0.0;
  double gap = 0.0;
  double prev = t0;
  for (std::size_t k = 0; k <= n; ++k) {
    const double t = k == n ? t1 : t0 + (t1 - t0) * static_cast<double>(k) / static_cast<double>(n);
    if (k > 0) gap = std::max(gap, up(CGAL::abs(I(t) - I(prev))));
    prev = t;
    out.push_back(centre_of(p.at(t), reach));
  }
  const I sag = I(m) * CGAL::square(I(gap)) / I(8.0);
  return up(sag + I(reach) + I(m) * (I(end.sup()) - I(end.inf())));
}

// A curved arrow shaft is certified as a polyline of 12 chords, not as its arc: the vertices
// are the arc's points at 12 equal angle steps from tail to tip, the ends being tail and tip
// (recognize.hpp, ShapeParams::shaft_bulge; the recognizer's clean path). The arc's midpoint is
// the 6th vertex, so each half (tail to midpoint, midpoint to tip) has 6 chords.
constexpr std::size_t kShaftHalfChords = 6;

// The chords of circle c from x to y (both on it in exact arithmetic; boxes here) at m equal
// angle steps: the vertex k is c.at(t_k), t_k = ax + (ay - ax) k / m with double angles ax, ay
// of x and y. Returns sigma, the farthest a vertex strays from the exact one at angle
// alpha + (beta - alpha) k / m (alpha, beta the exact angles of x and y): c.at(ax) is within e
// of x, so |ax - alpha| <= (pi / 2) e / R (a chord is at least 2 / pi of its arc below a half
// turn), the same for ay; t_k errs from its real formula by under 2^-47 (|angles| < 4 pi); so
// each vertex is within (pi / 2) e + R 2^-47 of the exact one along the circle, plus its box.
// Corresponding vertices that close keep the chords (pointwise) that close.
double equal_chords(const Curve& c, const IPoint& x, const IPoint& y, std::size_t m,
                    std::vector<PointD>& out) {
  double ignore = 0.0;
  const PointD cm = centre_of(c.c, ignore);
  const PointD xm = centre_of(x, ignore), ym = centre_of(y, ignore);
  const double ax = std::atan2(xm.y - cm.y, xm.x - cm.x);
  double s = std::atan2(ym.y - cm.y, ym.x - cm.x) - ax;
  if (s > std::numbers::pi) s -= 2.0 * std::numbers::pi;
  if (s <= -std::numbers::pi) s += 2.0 * std::numbers::pi;
  if (std::abs(s) > 3.0)
    throw InvalidInput("clean shape: the shaft arc is too close to a half circle");
  const double ay = ax + s;
  double reach = 0.0;
  for (std::size_t k = 0; k <= m; ++k) {
    const double t = k == m ? ay : ax + (ay - ax) * static_cast<double>(k) / static_cast<double>(m);
    out.push_back(centre_of(c.at(t), reach));
  }
  const double e =
      std::max(reach_to(c.at(ax), xm) + reach_to(x, xm), reach_to(c.at(ay), ym) + reach_to(y, ym));
  const I half_pi(std::numbers::pi / 2.0, std::nextafter(std::numbers::pi / 2.0, INFINITY));
  return up(I(reach) + half_pi * I(e) + c.a * I(0x1p-47));
}

void check_finite(PointD p) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
    throw InvalidInput("clean shape: a point is not finite");
  }
}

// tail -> tip along the shaft: straight, or the 12 chords of the circular arc through the point
// `bulge` to the left of the chord's midpoint (two halves: each is half of an arc shorter than a
// circle).
double shaft(PointD tail, PointD tip, double bulge, std::vector<PointD>& out) {
  if (bulge == 0.0 || (tail.x == tip.x && tail.y == tip.y)) {
    out = {tail, tip};
    return 0.0;
  }
  const IPoint t{I(tail.x), I(tail.y)}, p{I(tip.x), I(tip.y)};
  const I dx = p.x - t.x, dy = p.y - t.y;
  const I c = CGAL::sqrt(dx * dx + dy * dy);
  const IPoint n{-dy / c, dx / c};
  const I b(bulge);
  const IPoint mid{(t.x + p.x) / I(2.0) + b * n.x, (t.y + p.y) / I(2.0) + b * n.y};
  const I r = (c * c / I(4.0) + b * b) / (I(2.0) * CGAL::abs(b));
  // centre = mid - sign(b) r n = chord midpoint + (b - sign(b) r) n
  const I off = bulge > 0 ? b - r : b + r;
  Curve circle{{(t.x + p.x) / I(2.0) + off * n.x, (t.y + p.y) / I(2.0) + off * n.y}, r, r};
  std::vector<PointD> first, second;
  const double s1 = equal_chords(circle, t, mid, kShaftHalfChords, first);
  const double s2 = equal_chords(circle, mid, p, kShaftHalfChords, second);
  first.front() = tail; // the exact ends (within sigma of the vertices replaced)
  second.back() = tip;
  out = first;
  out.insert(out.end(), second.begin() + 1, second.end());
  return std::max(s1, s2);
}

ShapeChains curve_chains(ShapeClass shape, const ShapeParams& p, double target) {
  check_finite(p.center);
  const bool ellipse = shape == ShapeClass::kEllipse;
  const double a = p.radius_x, b = ellipse ? p.radius_y : p.radius_x;
  if (!(a > 0) || !(b > 0) || !std::isfinite(a) || !std::isfinite(b) ||
      !std::isfinite(p.rotation) || !std::isfinite(p.start_angle) ||
      !std::isfinite(p.sweep_angle)) {
    throw InvalidInput("clean shape: radii must be finite and > 0, angles finite");
  }
  Curve curve{{I(p.center.x), I(p.center.y)}, I(a), I(b)};
  if (ellipse) {
    curve.cos_r = icos(p.rotation);
    curve.sin_r = isin(p.rotation);
  }
  ShapeChains out;
  out.chains.emplace_back();
  if (shape == ShapeClass::kArc) {
    if (std::abs(p.sweep_angle) > 7.0) throw InvalidInput("clean shape: the arc sweeps too far");
    out.deviation =
        chords(curve, p.start_angle, I(p.start_angle) + I(p.sweep_angle), target, out.chains[0]);
  } else {
    // The whole curve: t over [0, 2 pi], 2 pi enclosed by the doubles around it.
    const double two_pi = 2.0 * std::numbers::pi;
    out.deviation =
        chords(curve, 0.0, I(two_pi, std::nextafter(two_pi, INFINITY)), target, out.chains[0]);
  }
  return out;
}

ShapeChains arrow_chains(ShapeClass shape, const ShapeParams& p) {
  const std::vector<PointD>& v = p.vertices;
  const std::size_t need = shape == ShapeClass::kDoubleArrow ? 6 : 4;
  if (v.size() != need) {
    throw InvalidInput("clean shape: an arrow needs " + std::to_string(need) + " vertices");
  }
  if (!std::isfinite(p.shaft_bulge)) throw InvalidInput("clean shape: shaft_bulge not finite");
  ShapeChains out;
  out.chains.emplace_back();
  // A shaft that stops short of the tip ends at shaft_end: the head is a chain of its own.
  if (p.shaft_end) {
    if (need != 4 || p.shaft_bulge != 0.0)
      throw InvalidInput("clean shape: only a single arrow's straight or bent shaft stops short");
    check_finite(*p.shaft_end);
  }
  const PointD stop = p.shaft_end.value_or(v[1]);
  if (p.shaft_bends.empty()) {
    out.deviation = shaft(v[0], stop, p.shaft_bulge, out.chains[0]);
  } else {
    // A bent shaft: the exact polyline tail -> bends -> tip.
    if (p.shaft_bulge != 0.0)
      throw InvalidInput("clean shape: a shaft is bent or curved, not both");
    if (p.shaft_bends.size() > 2) throw InvalidInput("clean shape: a shaft has at most 2 bends");
    for (const PointD& b : p.shaft_bends) check_finite(b);
    out.chains[0] = {v[0]};
    out.chains[0].insert(out.chains[0].end(), p.shaft_bends.begin(), p.shaft_bends.end());
    out.chains[0].push_back(stop);
  }
  out.chains.push_back({v[1], v[2]});
  out.chains.push_back({v[1], v[3]});
  if (need == 6) {
    out.chains.push_back({v[0], v[4]});
    out.chains.push_back({v[0], v[5]});
  }
  return out;
}

} // namespace

ShapeChains shape_chains(ShapeClass shape, const ShapeParams& params, double target) {
  if (!(target > 0) || !std::isfinite(target)) {
    throw InvalidInput("clean shape: the deviation target must be positive");
  }
  for (const PointD& v : params.vertices) check_finite(v);
  switch (shape) {
    case ShapeClass::kFreeform:
      throw InvalidInput("clean shape: freeform has no clean shape");
    case ShapeClass::kCircle:
    case ShapeClass::kEllipse:
    case ShapeClass::kArc:
      return curve_chains(shape, params, target);
    case ShapeClass::kArrow:
    case ShapeClass::kDoubleArrow:
      return arrow_chains(shape, params);
    case ShapeClass::kDot: // the point itself, as a zero-length chain
      if (params.vertices.size() != 1) throw InvalidInput("clean shape: a dot has 1 vertex");
      return {{{params.vertices[0], params.vertices[0]}}, 0.0};
    case ShapeClass::kSegment:
    case ShapeClass::kPolyline:
      if (params.vertices.size() < 2) throw InvalidInput("clean shape: needs 2 or more vertices");
      if (shape == ShapeClass::kSegment && params.vertices.size() != 2) {
        throw InvalidInput("clean shape: a segment has 2 vertices");
      }
      return {{params.vertices}, 0.0};
    default: {
      if (params.vertices.size() < 3) throw InvalidInput("clean shape: a polygon needs 3 corners");
      std::vector<PointD> ring = params.vertices;
      ring.push_back(ring.front());
      return {{ring}, 0.0};
    }
  }
}

} // namespace penshape::verify
