// The rotated frame of the branch-and-bound searches: points rotated by -theta about their
// centroid, and the way back to a placement of the template (rotation.hpp, methods 2 and 3).
#include <algorithm>
#include <cmath>

#include "rotation_internal.hpp"

namespace penshape::annulus::detail {

RotatedFrame::RotatedFrame(const std::vector<PointD>& points) : points_(points) {
  double sx = 0.0;
  double sy = 0.0;
  for (const PointD& q : points) {
    sx += q.x;
    sy += q.y;
    magnitude_ = std::max({magnitude_, std::abs(q.x), std::abs(q.y)});
  }
  const double n = static_cast<double>(points.size());
  centre_ = {sx / n, sy / n};
  rho_i_.reserve(points.size());
  for (const PointD& q : points) {
    // Rounded up by a relative 1e-12: a bound, not an estimate.
    const double r = std::hypot(q.x - centre_.x, q.y - centre_.y) * (1.0 + 1e-12);
    rho_i_.push_back(r);
    rho_ = std::max(rho_, r);
  }
}

RotatedFrame::Angle RotatedFrame::angle(double theta) {
  Angle a{};
  a.u = std::tan(0.5 * theta);
  const double u2 = a.u * a.u;
  a.c = (1.0 - u2) / (1.0 + u2);
  a.s = 2.0 * a.u / (1.0 + u2);
  a.theta = 2.0 * std::atan(a.u);
  return a;
}

std::vector<PointD> RotatedFrame::rotated(const Angle& a) const {
  std::vector<PointD> out;
  out.reserve(points_.size());
  for (const PointD& q : points_) {
    const double dx = q.x - centre_.x;
    const double dy = q.y - centre_.y;
    out.push_back({centre_.x + a.c * dx + a.s * dy, centre_.y - a.s * dx + a.c * dy});
  }
  return out;
}

Placement RotatedFrame::placement(const Angle& a, PointD t) const {
  const double dx = centre_.x - t.x;
  const double dy = centre_.y - t.y;
  Placement pl;
  pl.tan_half_theta = a.u;
  pl.theta = a.theta;
  pl.tx = centre_.x - (a.c * dx - a.s * dy);
  pl.ty = centre_.y - (a.s * dx + a.c * dy);
  return pl;
}

double RotatedFrame::slack(const TemplatePolygon& p, double delta) const {
  double extent = 0.0;
  for (const PointD& v : p.vertices()) extent = std::max({extent, std::abs(v.x), std::abs(v.y)});
  return 1e-9 * (magnitude_ + extent + delta);
}

double angle_reach(const RotatedFrame::Angle& a, double lo, double hi) {
  return std::max(a.theta - lo, hi - a.theta) * (1.0 + 1e-12) + 1e-15;
}

} // namespace penshape::annulus::detail
