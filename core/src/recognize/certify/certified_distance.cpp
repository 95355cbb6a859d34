// Certified distances of the path certificates (see certified_distance.hpp).
#include "recognize/certify/certified_distance.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "recognize/fitting/ellipse_foot.hpp"

namespace penshape::recognize_detail {
namespace {

using detail::enclose;
using detail::IntervalNT;
using detail::IPoint;
using Guard = CGAL::Protect_FPU_rounding<true>;

// The nearest segment of the polyline's pieces to p, in doubles (the proposal): a jump between
// two pieces is no segment of the shape, so it is never proposed (the bound is then the distance
// to a segment of the shape, >= the distance to the shape, the union of its pieces).
std::size_t nearest_segment(PointD p, const CleanShape& shape) {
  const std::vector<PointD>& path = shape.path;
  std::size_t best = 0;
  double best2 = INFINITY;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    if (!shape.joined(i)) continue;
    const double d2 = segment_distance2(p, path[i], path[i + 1]);
    if (d2 < best2) {
      best2 = d2;
      best = i;
    }
  }
  return best;
}

// The arc's parameter nearest p: the radial angle when inside the swept range, else the nearer
// end (the proposal; exactness is not needed).
double arc_foot(PointD p, const CleanShape& c) {
  const double a = std::atan2(p.y - c.center.y, p.x - c.center.x);
  const double lo = std::min(c.t0, c.t0 + c.sweep);
  double rel = std::fmod(a - lo, 2.0 * std::numbers::pi);
  if (rel < 0) rel += 2.0 * std::numbers::pi;
  // Kept within the double range [t0, t0 + sweep]: its rounding is CertifiedShape::end_slack.
  if (rel <= std::abs(c.sweep)) return std::min(lo + rel, std::max(c.t0, c.t0 + c.sweep));
  const double e0 = distance(p, c.at(c.t0));
  const double e1 = distance(p, c.at(c.t0 + c.sweep));
  return e0 <= e1 ? c.t0 : c.t0 + c.sweep;
}

} // namespace

IPoint point_on(PointD a, PointD b, std::size_t k, std::size_t n) {
  const Guard rounding;
  const IntervalNT f = IntervalNT(static_cast<double>(k)) / IntervalNT(static_cast<double>(n));
  return {IntervalNT(a.x) + f * (IntervalNT(b.x) - IntervalNT(a.x)),
          IntervalNT(a.y) + f * (IntervalNT(b.y) - IntervalNT(a.y))};
}

double half_piece(PointD a, PointD b, std::size_t n) {
  const Guard rounding;
  const IPoint ia = enclose(a), ib = enclose(b);
  return (CGAL::sqrt(CGAL::square(ib.x - ia.x) + CGAL::square(ib.y - ia.y)) /
          IntervalNT(2.0 * static_cast<double>(n)))
      .sup();
}

double sum_up(std::initializer_list<double> terms) {
  const Guard rounding;
  IntervalNT s(0.0);
  for (const double t : terms) s += IntervalNT(t);
  return s.sup();
}

double upper_to_segment(const IPoint& box, const Segment& s) {
  const Guard rounding;
  return detail::distance_upper(box, s.a, s.b);
}

CertifiedShape::CertifiedShape(const CleanShape& shape) : shape_(shape) {
  if (shape.kind == CleanShape::Kind::kPolyline) return;
  if (shape.kind == CleanShape::Kind::kEllipse) {
    cos_r_ = detail::enclose_cos(shape.rotation);
    sin_r_ = detail::enclose_sin(shape.rotation);
  }
  const Guard rounding;
  const double speed =
      std::max(shape.rx, shape.kind == CleanShape::Kind::kCircle ? shape.rx : shape.ry);
  // The end t0 + sweep is rounded; a full curve's 2 pi lies between its double and the next.
  const IntervalNT end =
      shape.full_curve()
          ? IntervalNT(2.0 * std::numbers::pi, std::nextafter(2.0 * std::numbers::pi, INFINITY))
          : IntervalNT(shape.t0) + IntervalNT(shape.sweep);
  end_slack_ = (IntervalNT(speed) * (IntervalNT(end.sup()) - IntervalNT(end.inf()))).sup();
}

IPoint CertifiedShape::curve_point(double t) const {
  const IntervalNT ct = detail::enclose_cos(t), st = detail::enclose_sin(t);
  const CleanShape& s = shape_;
  const Guard rounding;
  const IntervalNT ex = IntervalNT(s.rx) * ct;
  const IntervalNT ey = IntervalNT(s.kind == CleanShape::Kind::kCircle ? s.rx : s.ry) * st;
  return {IntervalNT(s.center.x) + cos_r_ * ex - sin_r_ * ey,
          IntervalNT(s.center.y) + sin_r_ * ex + cos_r_ * ey};
}

double CertifiedShape::upper(const IPoint& box, PointD near) const {
  const CleanShape& s = shape_;
  switch (s.kind) {
    case CleanShape::Kind::kPolyline: {
      const Guard rounding;
      if (s.path.size() == 1) return detail::distance_upper(box, enclose(s.path[0]));
      const std::size_t i = nearest_segment(near, s);
      return detail::distance_upper(box, s.path[i], s.path[i + 1]);
    }
    case CleanShape::Kind::kCircle: {
      if (s.full_curve()) {
        const Guard rounding;
        const IntervalNT r = CGAL::sqrt(CGAL::square(box.x - IntervalNT(s.center.x)) +
                                        CGAL::square(box.y - IntervalNT(s.center.y)));
        return CGAL::abs(r - IntervalNT(s.rx)).sup();
      }
      const IPoint foot = curve_point(arc_foot(near, s));
      const Guard rounding;
      return detail::distance_upper(box, foot);
    }
    case CleanShape::Kind::kEllipse: {
      // Into the frame (first quadrant by symmetry), then the distance to (a cos t, b sin t).
      const PointD d = near - s.center;
      const double c = std::cos(s.rotation), sn = std::sin(s.rotation);
      const double t = ellipse_foot_parameter(std::abs(c * d.x + sn * d.y),
                                              std::abs(-sn * d.x + c * d.y), s.rx, s.ry);
      const IntervalNT ct = detail::enclose_cos(t), st = detail::enclose_sin(t);
      const Guard rounding;
      const IntervalNT dx = box.x - IntervalNT(s.center.x), dy = box.y - IntervalNT(s.center.y);
      const IntervalNT x = CGAL::abs(cos_r_ * dx + sin_r_ * dy);
      const IntervalNT y = CGAL::abs(cos_r_ * dy - sin_r_ * dx);
      return CGAL::sqrt(CGAL::square(x - IntervalNT(s.rx) * ct) +
                        CGAL::square(y - IntervalNT(s.ry) * st))
          .sup();
    }
  }
  return INFINITY;
}

double CertifiedShape::farthest_from(const SegmentIndex& index, double h) const {
  return farthest_from(
      [&](PointD q, double floor) {
        std::uint32_t id = 0;
        (void)index.nearest_above(q, floor, id);
        return index.segment(id);
      },
      h);
}

double CertifiedShape::farthest_from(const std::function<Segment(PointD, double)>& nearest,
                                     double h) const {
  const CleanShape& s = shape_;
  double worst = 0.0; // certified so far
  double half = 0.0;  // largest half step
  auto visit = [&](const IPoint& box) {
    const PointD q{0.5 * (box.x.inf() + box.x.sup()), 0.5 * (box.y.inf() + box.y.sup())};
    worst = std::max(worst, upper_to_segment(box, nearest(q, worst)));
  };
  if (s.kind == CleanShape::Kind::kPolyline) {
    // Several pieces: the sup over their union is the greatest of the sups over each piece, and
    // every segment of every piece is visited (a jump is none: its points are not the shape's).
    if (s.path.size() == 1) visit(enclose(s.path[0]));
    for (std::size_t i = 0; i + 1 < s.path.size(); ++i) {
      if (!s.joined(i)) continue;
      const PointD a = s.path[i], b = s.path[i + 1];
      const auto n = static_cast<std::size_t>(std::max(1.0, std::ceil(distance(a, b) / h)));
      half = std::max(half, half_piece(a, b, n));
      for (std::size_t k = 0; k <= n; ++k) visit(point_on(a, b, k, n));
    }
    return sum_up({worst, half});
  }
  // |d/dt at(t)| <= speed: parameter steps dt move at most speed dt along the curve.
  const double speed = std::max(s.rx, s.kind == CleanShape::Kind::kCircle ? s.rx : s.ry);
  const auto n = static_cast<std::size_t>(std::max(8.0, std::ceil(std::abs(s.sweep) * speed / h)));
  double prev = s.t0;
  for (std::size_t k = 0; k <= n; ++k) {
    const double t = s.t0 + s.sweep * static_cast<double>(k) / static_cast<double>(n);
    if (k > 0) {
      const Guard rounding;
      half = std::max(
          half, (IntervalNT(speed) * CGAL::abs(IntervalNT(t) - IntervalNT(prev)) / IntervalNT(2.0))
                    .sup());
    }
    prev = t;
    visit(curve_point(t));
  }
  return sum_up({worst, half});
}

double segment_to_shape(PointD a, PointD b, double h, const CertifiedShape& shape) {
  const auto n = static_cast<std::size_t>(std::max(1.0, std::ceil(distance(a, b) / h)));
  double worst = 0.0;
  for (std::size_t k = 0; k <= n; ++k) {
    const double f = static_cast<double>(k) / static_cast<double>(n);
    worst = std::max(worst, shape.upper(point_on(a, b, k, n), a + f * (b - a)));
  }
  return sum_up({worst, half_piece(a, b, n)});
}

} // namespace penshape::recognize_detail
