// Sampling and distances of clean shapes.
#include "recognize/fitting/clean_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "penshape/core/bulge_arc.hpp"
#include "recognize/fitting/ellipse_foot.hpp"

namespace penshape::recognize_detail {

PointD CleanShape::at(double t) const {
  const double c = std::cos(rotation);
  const double s = std::sin(rotation);
  const double ex = rx * std::cos(t);
  const double ey = (kind == Kind::kCircle ? rx : ry) * std::sin(t);
  return {center.x + c * ex - s * ey, center.y + s * ex + c * ey};
}

std::vector<PointD> CleanShape::sample(double h) const {
  std::vector<PointD> out;
  if (kind == Kind::kPolyline) {
    if (path.empty()) return out;
    out.push_back(path.front());
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      if (!joined(i)) { // the next piece starts: its first vertex only
        out.push_back(path[i + 1]);
        continue;
      }
      const double len = distance(path[i], path[i + 1]);
      const auto pieces = static_cast<std::size_t>(std::max(1.0, std::ceil(len / h)));
      for (std::size_t k = 1; k <= pieces; ++k) {
        const double f = static_cast<double>(k) / static_cast<double>(pieces);
        out.push_back(path[i] + f * (path[i + 1] - path[i]));
      }
    }
    return out;
  }
  // |d/dt at(t)| <= max(rx, ry): a parameter step of h / max(rx, ry) moves at most h along it.
  const double speed = std::max(rx, kind == Kind::kCircle ? rx : ry);
  const auto pieces =
      static_cast<std::size_t>(std::max(8.0, std::ceil(std::abs(sweep) * speed / h)));
  out.reserve(pieces + 1);
  for (std::size_t k = 0; k <= pieces; ++k) {
    out.push_back(at(t0 + sweep * static_cast<double>(k) / static_cast<double>(pieces)));
  }
  return out;
}

double CleanShape::length() const {
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    if (joined(i)) total += distance(path[i], path[i + 1]);
  }
  return total;
}

std::vector<PointD> shaft_path(PointD tail, PointD tip, double bulge,
                               const std::vector<PointD>& bends) {
  if (!bends.empty()) {
    std::vector<PointD> out{tail};
    out.insert(out.end(), bends.begin(), bends.end());
    out.push_back(tip);
    return out;
  }
  const double c = distance(tail, tip);
  if (bulge == 0.0 || c <= 0.0) return {tail, tip};
  const BulgeArc arc = bulge_arc(tail, tip, bulge);
  std::vector<PointD> out;
  for (std::size_t k = 0; k <= kShaftChords; ++k) {
    out.push_back(
        arc.at(arc.start + arc.sweep * static_cast<double>(k) / static_cast<double>(kShaftChords)));
  }
  out.front() = tail;
  out.back() = tip;
  return out;
}

std::vector<PointD> arrow_path(ShapeClass shape, const std::vector<PointD>& v, double bulge,
                               const std::vector<PointD>& bends,
                               const std::optional<PointD>& shaft_end) {
  const std::size_t need = shape == ShapeClass::kDoubleArrow ? 6 : 4;
  if (v.size() != need) throw InvalidInput("clean shape: an arrow needs its tail, tip and barbs");
  if (shaft_end) {
    // Two pieces: the shaft as far as it goes, then the head (the jump between is no part).
    std::vector<PointD> path = shaft_path(v[0], *shaft_end, 0.0, bends);
    path.insert(path.end(), {v[2], v[1], v[3]});
    return path;
  }
  // One path through every piece; the retraces do not change the set (group_recognize.hpp).
  std::vector<PointD> path;
  if (shape == ShapeClass::kDoubleArrow) path = {v[4], v[0], v[5], v[0]};
  const std::vector<PointD> shaft = shaft_path(v[0], v[1], bulge, bends);
  if (path.empty()) {
    path = shaft;
  } else {
    path.insert(path.end(), shaft.begin() + 1, shaft.end());
  }
  path.insert(path.end(), {v[2], v[1], v[3]});
  return path;
}

std::vector<std::size_t> arrow_jumps(const std::vector<PointD>& bends,
                                     const std::optional<PointD>& shaft_end) {
  if (!shaft_end) return {};
  return {bends.size() + 1};
}

namespace {

bool finite_point(PointD p) { return std::isfinite(p.x) && std::isfinite(p.y); }

CleanShape round_shape(ShapeClass shape, const ShapeParams& params) {
  CleanShape c;
  const bool ellipse = shape == ShapeClass::kEllipse;
  c.kind = ellipse ? CleanShape::Kind::kEllipse : CleanShape::Kind::kCircle;
  c.center = params.center;
  c.rx = params.radius_x;
  c.ry = ellipse ? params.radius_y : params.radius_x;
  c.rotation = ellipse ? params.rotation : 0.0;
  if (shape == ShapeClass::kArc) {
    c.t0 = params.start_angle;
    c.sweep = params.sweep_angle;
  }
  const bool radii_ok = c.rx > 0 && c.ry > 0 && std::isfinite(c.rx) && std::isfinite(c.ry);
  const bool angles_ok = std::isfinite(c.rotation) && std::isfinite(c.t0) &&
                         std::isfinite(c.sweep) &&
                         std::abs(c.sweep) <= 2.0 * std::numbers::pi + 1e-9;
  if (!finite_point(c.center) || !radii_ok || !angles_ok) {
    throw InvalidInput("clean shape: centre, radii and angles must be finite, radii > 0");
  }
  return c;
}

std::vector<PointD> checked_arrow_path(ShapeClass shape, const ShapeParams& params) {
  if (params.shaft_bends.size() > kMaxShaftBends) {
    throw InvalidInput("clean shape: an arrow's shaft has at most 2 bends");
  }
  for (const PointD& b : params.shaft_bends) {
    if (!finite_point(b)) throw InvalidInput("clean shape: a shaft bend is not finite");
  }
  if (!params.shaft_bends.empty() && params.shaft_bulge != 0.0) {
    throw InvalidInput("clean shape: a shaft is bent or curved, not both");
  }
  if (params.shaft_end) {
    if (shape != ShapeClass::kArrow || params.shaft_bulge != 0.0) {
      throw InvalidInput(
          "clean shape: only a single arrow's straight or bent shaft may stop short");
    }
    if (!finite_point(*params.shaft_end)) throw InvalidInput("clean shape: shaft_end not finite");
  }
  return arrow_path(shape, params.vertices, params.shaft_bulge, params.shaft_bends,
                    params.shaft_end);
}

} // namespace

CleanShape clean_shape_of(ShapeClass shape, const ShapeParams& params) {
  switch (shape) {
    case ShapeClass::kFreeform:
      throw InvalidInput("clean shape: freeform has no clean shape");
    case ShapeClass::kCircle:
    case ShapeClass::kArc:
    case ShapeClass::kEllipse:
      return round_shape(shape, params);
    default:
      break;
  }
  CleanShape c;
  c.kind = CleanShape::Kind::kPolyline;
  c.path = params.vertices;
  if (c.path.empty()) throw InvalidInput("clean shape: no vertices");
  for (const PointD& v : c.path) {
    if (!finite_point(v)) throw InvalidInput("clean shape: a vertex is not finite");
  }
  if (shape == ShapeClass::kArrow || shape == ShapeClass::kDoubleArrow) {
    c.path = checked_arrow_path(shape, params);
    c.jumps = arrow_jumps(params.shaft_bends, params.shaft_end);
  } else if (shape != ShapeClass::kSegment && shape != ShapeClass::kPolyline) {
    c.path.push_back(c.path.front()); // polygons are closed
  }
  return c;
}

double arc_distance(PointD p, const CleanShape& circle) {
  const PointD d = p - circle.center;
  const double r = norm(d);
  if (circle.full_curve()) return std::abs(r - circle.rx);
  // Inside the swept angular range the nearest point is radial; outside, an arc end.
  const double a = std::atan2(d.y, d.x);
  const double lo = std::min(circle.t0, circle.t0 + circle.sweep);
  const double span = std::abs(circle.sweep);
  double rel = std::fmod(a - lo, 2.0 * std::numbers::pi);
  if (rel < 0) rel += 2.0 * std::numbers::pi;
  if (rel <= span) return std::abs(r - circle.rx);
  const double e0 = distance(p, circle.at(circle.t0));
  const double e1 = distance(p, circle.at(circle.t0 + circle.sweep));
  return std::min(e0, e1);
}

double ellipse_foot_parameter(double x, double y, double a, double b) {
  double t = std::atan2(a * y, b * x);
  for (int it = 0; it < 6; ++it) {
    const double st = std::sin(t), ct = std::cos(t);
    const double g = (a * a - b * b) * st * ct - a * x * st + b * y * ct;
    const double dg = (a * a - b * b) * (ct * ct - st * st) - a * x * ct - b * y * st;
    if (dg == 0.0) break;
    t = std::clamp(t - g / dg, 0.0, std::numbers::pi / 2);
  }
  return t;
}

double ellipse_distance(PointD p, const CleanShape& e) {
  // Into the ellipse's frame, first quadrant (the distance is symmetric in both axes).
  const PointD d = p - e.center;
  const double c = std::cos(e.rotation);
  const double s = std::sin(e.rotation);
  const double x = std::abs(c * d.x + s * d.y);
  const double y = std::abs(-s * d.x + c * d.y);
  const double a = e.rx;
  const double b = e.ry;
  const double t = ellipse_foot_parameter(x, y, a, b);
  return std::hypot(x - a * std::cos(t), y - b * std::sin(t));
}

namespace {

// The distance to a polyline of several pieces: the least over the segments of every piece.
double pieces_distance(PointD p, const CleanShape& c) {
  double best2 = INFINITY;
  for (std::size_t i = 0; i + 1 < c.path.size(); ++i) {
    if (c.joined(i)) best2 = std::min(best2, segment_distance2(p, c.path[i], c.path[i + 1]));
  }
  return std::sqrt(best2);
}

} // namespace

double CleanShape::distance_to(PointD p) const {
  switch (kind) {
    case Kind::kPolyline:
      return jumps.empty() ? polyline_distance(p, path) : pieces_distance(p, *this);
    case Kind::kCircle:
      return arc_distance(p, *this);
    case Kind::kEllipse:
      return ellipse_distance(p, *this);
  }
  return INFINITY;
}

namespace {

// approximate_ellipse_distance with the rotation's cosine and sine given (computed once per shape
// by the callers that measure many points).
double sampson_distance(PointD p, const CleanShape& e, double c, double s) {
  const PointD d = p - e.center;
  const double x = (c * d.x + s * d.y) / e.rx;
  const double y = (-s * d.x + c * d.y) / e.ry;
  // Sampson's first-order distance to F = x^2 + y^2 - 1 in the scaled frame.
  const double g = 2.0 * std::sqrt(x * x / (e.rx * e.rx) + y * y / (e.ry * e.ry));
  const double f = std::abs(x * x + y * y - 1.0);
  return g > 0 ? f / g : std::max(e.rx, e.ry);
}

} // namespace

double approximate_ellipse_distance(PointD p, const CleanShape& e) {
  return sampson_distance(p, e, std::cos(e.rotation), std::sin(e.rotation));
}

double max_distance(std::span<const PointD> points, const CleanShape& shape) {
  double worst = 0.0;
  if (shape.kind == CleanShape::Kind::kEllipse) {
    const double c = std::cos(shape.rotation);
    const double s = std::sin(shape.rotation);
    for (const PointD& p : points) worst = std::max(worst, sampson_distance(p, shape, c, s));
    return worst;
  }
  for (const PointD& p : points) worst = std::max(worst, shape.distance_to(p));
  return worst;
}

} // namespace penshape::recognize_detail

namespace penshape::recognize_detail {

double rms_distance(std::span<const PointD> points, const CleanShape& shape) {
  double sum = 0.0;
  for (const PointD& p : points) {
    const double d = shape.kind == CleanShape::Kind::kEllipse
                         ? approximate_ellipse_distance(p, shape)
                         : shape.distance_to(p);
    sum += d * d;
  }
  return points.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(points.size()));
}

} // namespace penshape::recognize_detail

namespace penshape {

std::vector<std::vector<PointD>> clean_pieces(ShapeClass shape, const ShapeParams& params,
                                              const std::vector<PointD>& clean) {
  // The layout of arrow_path: the shaft's vertices up to shaft_end, then the head's three.
  const std::size_t shaft = params.shaft_bends.size() + 2;
  if (shape != ShapeClass::kArrow || !params.shaft_end || clean.size() != shaft + 3) {
    return {clean};
  }
  const auto cut = clean.begin() + static_cast<std::ptrdiff_t>(shaft);
  return {std::vector<PointD>(clean.begin(), cut), std::vector<PointD>(cut, clean.end())};
}

} // namespace penshape
