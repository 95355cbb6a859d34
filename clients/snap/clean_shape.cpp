// Sampling clean curves: a uniform parameter step dt on a curve with |B''| <= M keeps every chord
// within M dt^2 / 8 of the curve; for an ellipse (a cos t, b sin t) rotated, M = max(a, b).
#include "clean_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace penshape::snap {

bool is_snap(const Recognition& r) {
  if (r.shape == ShapeClass::kFreeform || !r.certificate.certified) return false;
  // Only an answer with the geometry of its class is written (a daemon could send less).
  const std::size_t n = r.params.vertices.size();
  switch (r.shape) {
    case ShapeClass::kSegment:
      return n == 2;
    case ShapeClass::kPolyline:
      return n >= 2;
    case ShapeClass::kCircle:
    case ShapeClass::kArc:
      return r.params.radius_x > 0;
    case ShapeClass::kEllipse:
      return r.params.radius_x > 0 && r.params.radius_y > 0;
    default:
      return n >= 3;
  }
}

std::vector<PointD> clean_polyline(const Recognition& r) {
  const ShapeParams& p = r.params;
  const bool round = r.shape == ShapeClass::kCircle || r.shape == ShapeClass::kEllipse ||
                     r.shape == ShapeClass::kArc;
  if (!round) {
    std::vector<PointD> out = p.vertices;
    const bool open = r.shape == ShapeClass::kSegment || r.shape == ShapeClass::kPolyline;
    if (!open && !out.empty()) out.push_back(out.front());
    return out;
  }
  const double a = p.radius_x, b = r.shape == ShapeClass::kEllipse ? p.radius_y : p.radius_x;
  const double eps = r.certificate.epsilon;
  // Also at most a tenth of the pen radius, so the facets do not show in the ink.
  const double sag = std::max(
      std::min({eps - r.certificate.bound, eps / 20, r.certificate.pen_radius / 10}), eps * 1e-3);
  const double dt = std::sqrt(8 * sag / std::max(a, b));
  const double t0 = r.shape == ShapeClass::kArc ? p.start_angle : 0.0;
  const double sweep = r.shape == ShapeClass::kArc ? p.sweep_angle : 2 * std::numbers::pi;
  const auto n = static_cast<std::size_t>(std::clamp(std::ceil(std::abs(sweep) / dt), 8.0, 1e5));
  const double c = std::cos(p.rotation), s = std::sin(p.rotation);
  std::vector<PointD> out;
  for (std::size_t i = 0; i <= n; ++i) {
    const double t = t0 + sweep * static_cast<double>(i) / static_cast<double>(n);
    const double x = a * std::cos(t), y = b * std::sin(t);
    out.push_back({p.center.x + c * x - s * y, p.center.y + s * x + c * y});
  }
  return out;
}

} // namespace penshape::snap
