// Sampling clean curves: a uniform parameter step dt on a curve with |B''| <= M keeps every chord
// within M dt^2 / 8 of the curve; for an ellipse (a cos t, b sin t) rotated, M = max(a, b).
#include "clean_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "penshape/core/bulge_arc.hpp"

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
    case ShapeClass::kArrow:
    case ShapeClass::kDoubleArrow:
      return n == (r.shape == ShapeClass::kArrow ? 4u : 6u) && r.params.shaft_bends.size() <= 2 &&
             (r.params.shaft_bends.empty() || r.params.shaft_bulge == 0);
    default:
      return n >= 3;
  }
}

namespace {

// The chord step dt for a curve of largest radius `radius`: chords within the sag below.
double chord_step(const Recognition& r, double radius) {
  const double eps = r.certificate.epsilon;
  // Also at most a tenth of the pen radius, so the facets do not show in the ink.
  const double sag = std::max(
      std::min({eps - r.certificate.bound, eps / 20, r.certificate.pen_radius / 10}), eps * 1e-3);
  return std::sqrt(8 * sag / radius);
}

// The circular arc from a to b whose midpoint lies `bulge` to the left of the chord a -> b.
std::vector<PointD> bowed(const Recognition& r, PointD a, PointD b, double bulge) {
  if (!(distance(a, b) > 0) || bulge == 0) return {a, b};
  const BulgeArc arc = bulge_arc(a, b, bulge);
  const auto n_chords = static_cast<std::size_t>(
      std::clamp(std::ceil(std::abs(arc.sweep) / chord_step(r, arc.radius)), 8.0, 1e5));
  std::vector<PointD> out;
  for (std::size_t i = 0; i <= n_chords; ++i) {
    out.push_back(
        arc.at(arc.start + arc.sweep * static_cast<double>(i) / static_cast<double>(n_chords)));
  }
  out.front() = a;
  out.back() = b;
  return out;
}

} // namespace

std::vector<std::vector<PointD>> arrow_pieces(const Recognition& r) {
  const ShapeParams& p = r.params;
  const std::vector<PointD>& v = p.vertices;
  // A curved shaft: the recognizer's clean path is what was certified (chords of the arc).
  if (p.shaft_bulge != 0 && !r.clean.empty()) return {r.clean};
  std::vector<PointD> shaft{v[0]};
  shaft.insert(shaft.end(), p.shaft_bends.begin(), p.shaft_bends.end());
  shaft.push_back(p.shaft_end.value_or(v[1])); // a shaft may stop short of the tip
  if (p.shaft_bulge != 0 && p.shaft_bends.empty()) shaft = bowed(r, v[0], v[1], p.shaft_bulge);
  std::vector<std::vector<PointD>> out{shaft, {v[2], v[1], v[3]}};
  if (v.size() == 6) out.push_back({v[4], v[0], v[5]});
  return out;
}

std::vector<std::vector<PointD>> clean_lines(const Recognition& r) {
  if (r.shape == ShapeClass::kArrow && r.params.shaft_end) return arrow_pieces(r);
  return {clean_polyline(r)};
}

std::vector<PointD> clean_polyline(const Recognition& r) {
  const ShapeParams& p = r.params;
  if (r.shape == ShapeClass::kArrow || r.shape == ShapeClass::kDoubleArrow) {
    // One line through every piece: the tail head and the head are retraced (the same ink).
    const std::vector<std::vector<PointD>> pieces = arrow_pieces(r);
    if (pieces.size() == 1) return pieces[0];
    std::vector<PointD> out;
    if (pieces.size() == 3) out = {pieces[2][0], pieces[2][1], pieces[2][2], pieces[2][1]};
    if (!out.empty()) out.pop_back(); // the shaft starts at the tail
    out.insert(out.end(), pieces[0].begin(), pieces[0].end());
    out.insert(out.end(), {pieces[1][0], pieces[1][1], pieces[1][2]});
    return out;
  }
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
