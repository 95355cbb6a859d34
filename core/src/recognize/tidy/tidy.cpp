// Tidy-up proposals (circle, right angles, equal sides, axis, parallel, connection), each kept
// only when certified on the strokes.
#include "recognize/tidy/tidy.hpp"

#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

#include "recognize/certify/ink_certificate.hpp"
#include "recognize/fitting/clean_shape.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
namespace {

struct Proposal {
  ShapeClass shape;
  ShapeParams params;
};

bool has_vertices(ShapeClass c) {
  return c != ShapeClass::kFreeform && c != ShapeClass::kCircle && c != ShapeClass::kEllipse &&
         c != ShapeClass::kArc;
}
bool is_closed_polygon(ShapeClass c) {
  return has_vertices(c) && c != ShapeClass::kSegment && c != ShapeClass::kPolyline &&
         c != ShapeClass::kArrow && c != ShapeClass::kDoubleArrow;
}

PointD rotate_about(PointD p, PointD c, double a) {
  const PointD d = p - c;
  return {c.x + std::cos(a) * d.x - std::sin(a) * d.y, c.y + std::sin(a) * d.x + std::cos(a) * d.y};
}

PointD mean_of(const std::vector<PointD>& v) {
  PointD s;
  for (const PointD& p : v) s = s + p;
  return (1.0 / static_cast<double>(v.size())) * s;
}

// The edges of a shape with vertices (polygons closed; an arrow's shaft only matters most: its
// chord, or a bent shaft's pieces).
std::vector<std::pair<PointD, PointD>> edges_of(ShapeClass c, const ShapeParams& p) {
  std::vector<PointD> v = p.vertices;
  std::vector<std::pair<PointD, PointD>> out;
  if (c == ShapeClass::kArrow || c == ShapeClass::kDoubleArrow) {
    v = {v[0]};
    v.insert(v.end(), p.shaft_bends.begin(), p.shaft_bends.end());
    v.push_back(p.vertices[1]);
  }
  for (std::size_t i = 0; i + 1 < v.size(); ++i) out.emplace_back(v[i], v[i + 1]);
  if (is_closed_polygon(c) && v.size() > 2) out.emplace_back(v.back(), v.front());
  return out;
}

// Direction (radians) of the longest edge, or of an ellipse's axis or a diamond's diagonal (its
// sides are equal: the diagonals are what a flowchart aligns).
std::optional<double> main_direction(ShapeClass c, const ShapeParams& p) {
  if (c == ShapeClass::kEllipse || c == ShapeClass::kDiamond) return p.rotation;
  if (!has_vertices(c) || p.vertices.size() < 2) return std::nullopt;
  double best = -1.0, angle = 0.0;
  for (const auto& [a, b] : edges_of(c, p)) {
    if (distance(a, b) > best) {
      best = distance(a, b);
      angle = std::atan2(b.y - a.y, b.x - a.x);
    }
  }
  return angle;
}

// Smallest signed turn taking direction `from` to `to` modulo `period`.
double turn_to(double from, double to, double period) {
  double d = std::fmod(to - from, period);
  if (d > period / 2) d -= period;
  if (d < -period / 2) d += period;
  return d;
}

Proposal rotated(ShapeClass c, ShapeParams p, double a) {
  const PointD centre = has_vertices(c) ? mean_of(p.vertices) : p.center;
  for (PointD& v : p.vertices) v = rotate_about(v, centre, a);
  for (PointD& v : p.shaft_bends) v = rotate_about(v, centre, a);
  if (p.shaft_end) p.shaft_end = rotate_about(*p.shaft_end, centre, a);
  p.center = rotate_about(p.center, centre, a);
  p.rotation += a;
  return {c, std::move(p)};
}

double corner_angle(PointD prev, PointD at, PointD next) {
  const PointD u = prev - at, v = next - at;
  return std::abs(std::atan2(cross(u, v), dot(u, v)));
}

double signed_area(const std::vector<PointD>& v) {
  double a = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) a += cross(v[i], v[(i + 1) % v.size()]);
  return a / 2.0;
}

// A rectangle (or square) centred at c along direction `angle` with half-sides a, b, turning
// the same way as `like`.
ShapeParams box(PointD c, double angle, double a, double b, const std::vector<PointD>& like) {
  const PointD u{std::cos(angle), std::sin(angle)}, n{-u.y, u.x};
  ShapeParams p;
  p.center = c;
  p.rotation = angle;
  p.vertices = {c + a * u + b * n, c - a * u + b * n, c - a * u - b * n, c + a * u - b * n};
  if (signed_area(like) * signed_area(p.vertices) < 0)
    std::reverse(p.vertices.begin(), p.vertices.end());
  return p;
}

std::optional<Proposal> circle_of(const Recognition& r) {
  if (r.shape != ShapeClass::kEllipse) return std::nullopt;
  const double lo = std::min(r.params.radius_x, r.params.radius_y);
  const double hi = std::max(r.params.radius_x, r.params.radius_y);
  if (lo < kRoundEllipse * hi) return std::nullopt;
  ShapeParams p;
  p.center = r.params.center;
  p.radius_x = p.radius_y = 0.5 * (lo + hi);
  return Proposal{ShapeClass::kCircle, p};
}

std::optional<Proposal> right_angles_of(const Recognition& r) {
  const std::vector<PointD>& v = r.params.vertices;
  if (r.shape == ShapeClass::kQuadrilateral && v.size() == 4) {
    for (std::size_t i = 0; i < 4; ++i) {
      const double a = corner_angle(v[(i + 3) % 4], v[i], v[(i + 1) % 4]);
      if (std::abs(a - std::numbers::pi / 2) > kRightAngleSlack) return std::nullopt;
    }
    const double angle = *main_direction(r.shape, r.params);
    const PointD c = mean_of(v), u{std::cos(angle), std::sin(angle)}, n{-u.y, u.x};
    double a = 0.0, b = 0.0;
    for (const PointD& p : v) {
      a += std::abs(dot(p - c, u)) / 4.0;
      b += std::abs(dot(p - c, n)) / 4.0;
    }
    return Proposal{ShapeClass::kRectangle, box(c, angle, a, b, v)};
  }
  if (r.shape != ShapeClass::kPolyline || v.size() < 3) return std::nullopt;
  ShapeParams p = r.params;
  bool changed = false;
  for (std::size_t i = 1; i + 1 < p.vertices.size(); ++i) {
    std::vector<PointD>& w = p.vertices;
    const PointD u = w[i - 1] - w[i], t = w[i + 1] - w[i];
    const double turn = std::atan2(cross(u, t), dot(u, t)); // signed corner angle
    const double want = turn > 0 ? std::numbers::pi / 2 : -std::numbers::pi / 2;
    if (std::abs(turn - want) > kRightAngleSlack || std::abs(turn - want) < kAlreadyExact) continue;
    for (std::size_t k = i + 1; k < w.size(); ++k) w[k] = rotate_about(w[k], w[i], want - turn);
    changed = true;
  }
  if (!changed) return std::nullopt;
  return Proposal{r.shape, p};
}

std::optional<Proposal> equal_sides_of(const Recognition& r) {
  const std::vector<PointD>& v = r.params.vertices;
  if (r.shape == ShapeClass::kRectangle && v.size() == 4) {
    const double a = distance(v[0], v[1]), b = distance(v[1], v[2]);
    if (std::abs(a - b) > kEqualSides * std::max(a, b)) return std::nullopt;
    const double angle = std::atan2(v[1].y - v[0].y, v[1].x - v[0].x);
    const double half = (a + b) / 4.0;
    return Proposal{ShapeClass::kSquare, box(mean_of(v), angle, half, half, v)};
  }
  if (r.shape != ShapeClass::kTriangle || v.size() != 3) return std::nullopt;
  double lo = INFINITY, hi = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double s = distance(v[i], v[(i + 1) % 3]);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
    sum += s;
  }
  if (hi - lo > kEqualSides * hi) return std::nullopt;
  const PointD c = mean_of(v);
  const double radius = (sum / 3.0) / std::sqrt(3.0);
  const double start = std::atan2(v[0].y - c.y, v[0].x - c.x);
  const double turn = signed_area(v) > 0 ? 1.0 : -1.0;
  ShapeParams p = r.params;
  for (std::size_t i = 0; i < 3; ++i) {
    const double a = start + turn * 2.0 * std::numbers::pi * static_cast<double>(i) / 3.0;
    p.vertices[i] = {c.x + radius * std::cos(a), c.y + radius * std::sin(a)};
  }
  p.center = c;
  return Proposal{r.shape, p};
}

std::optional<Proposal> axis_of(const Recognition& r) {
  const std::optional<double> dir = main_direction(r.shape, r.params);
  if (!dir) return std::nullopt;
  const double d = turn_to(*dir, std::round(*dir / (std::numbers::pi / 4)) * (std::numbers::pi / 4),
                           2.0 * std::numbers::pi);
  if (std::abs(d) > kAxisSlack || std::abs(d) < kAlreadyExact) return std::nullopt;
  return rotated(r.shape, r.params, d);
}

std::optional<Proposal> parallel_of(const Recognition& r,
                                    const std::vector<const Recognition*>& neighbours) {
  const std::optional<double> dir = main_direction(r.shape, r.params);
  if (!dir) return std::nullopt;
  double best = INFINITY;
  for (const Recognition* n : neighbours) {
    if (!has_vertices(n->shape) || n->params.vertices.size() < 2) continue;
    for (const auto& [a, b] : edges_of(n->shape, n->params)) {
      const double d = turn_to(*dir, std::atan2(b.y - a.y, b.x - a.x), std::numbers::pi);
      if (std::abs(d) < std::abs(best)) best = d;
    }
  }
  if (!(std::abs(best) <= kParallelSlack) || std::abs(best) < kAlreadyExact) return std::nullopt;
  return rotated(r.shape, r.params, best);
}

// The point of a neighbour an end should join: a vertex within epsilon, else the nearest point
// of its outline within epsilon.
std::optional<PointD> join_target(PointD end, double epsilon,
                                  const std::vector<const Recognition*>& neighbours) {
  std::optional<PointD> best;
  double best_d = epsilon;
  for (const Recognition* n : neighbours) {
    for (const PointD& v : n->params.vertices) {
      if (distance(v, end) <= best_d) {
        best_d = distance(v, end);
        best = v;
      }
    }
  }
  if (best) return best;
  for (const Recognition* n : neighbours) {
    const std::vector<PointD>& path = n->clean;
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      const double t = detail::proposed_foot_parameter(end, path[i], path[i + 1]);
      const PointD q = path[i] + t * (path[i + 1] - path[i]);
      if (distance(q, end) <= best_d) {
        best_d = distance(q, end);
        best = q;
      }
    }
  }
  return best;
}

std::optional<Proposal> connection_of(const Recognition& r,
                                      const std::vector<const Recognition*>& neighbours) {
  const ShapeClass c = r.shape;
  const bool arrow = c == ShapeClass::kArrow || c == ShapeClass::kDoubleArrow;
  if (c != ShapeClass::kSegment && c != ShapeClass::kPolyline && !arrow) return std::nullopt;
  ShapeParams p = r.params;
  std::vector<PointD>& v = p.vertices;
  bool changed = false;
  // The ends: first and last vertex; an arrow's tail (0) and tip (1), its barbs moving along.
  const std::size_t ends[2] = {0, arrow ? std::size_t{1} : v.size() - 1};
  for (const std::size_t e : ends) {
    const std::optional<PointD> target = join_target(v[e], r.epsilon, neighbours);
    if (!target || distance(*target, v[e]) < kAlreadyExact * r.epsilon) continue;
    const PointD shift = *target - v[e];
    v[e] = *target;
    if (arrow && e == 1) v[2] = v[2] + shift, v[3] = v[3] + shift;
    if (c == ShapeClass::kDoubleArrow && e == 0) v[4] = v[4] + shift, v[5] = v[5] + shift;
    changed = true;
  }
  if (!changed) return std::nullopt;
  if (arrow) p.center = 0.5 * (v[0] + v[1]);
  return Proposal{c, p};
}

// Certifies a proposal on the strokes; applies it to r when certified.
bool try_apply(Recognition& r, const UnionStroke& u, const std::function<const InkRegion*()>& ink,
               const std::optional<Proposal>& proposal) {
  if (!proposal) return false;
  CleanShape clean;
  try {
    clean = clean_shape_of(proposal->shape, proposal->params);
  } catch (const InvalidInput&) {
    return false;
  }
  Certificate cert = certify_union(u, clean, r.epsilon, r.pen_radius);
  if (!cert.certified) return false;
  if (const InkRegion* q = ink()) {
    cert = certify_ink(*q, clean, r.epsilon, r.pen_radius);
    if (!cert.certified) return false;
  }
  r.shape = proposal->shape;
  r.params = proposal->params;
  r.clean = clean.kind == CleanShape::Kind::kPolyline ? clean.path : clean.sample(u.size / 40.0);
  r.certificate = cert;
  r.confidence = std::clamp(1.0 - cert.bound / (2.0 * r.epsilon), 0.0, 1.0);
  return true;
}

} // namespace

std::vector<std::string> tidy_up(Recognition& r, const UnionStroke& u, const TidyConfig& config,
                                 const std::vector<const Recognition*>& neighbours,
                                 const InkPolygon* ink) {
  std::vector<std::string> applied;
  if (r.shape == ShapeClass::kFreeform || r.shape == ShapeClass::kDot) return applied;
  // Q is prepared once, and only when a proposal certified on the strokes is checked on it.
  std::optional<InkRegion> region;
  const std::function<const InkRegion*()> q = [&]() -> const InkRegion* {
    if (ink == nullptr) return nullptr;
    if (!region) region = prepare_ink(*ink, r.epsilon);
    return &*region;
  };
  auto step = [&](bool enabled, const char* name, auto&& propose) {
    if (enabled && try_apply(r, u, q, propose())) applied.emplace_back(name);
  };
  step(config.circle, "circle", [&] { return circle_of(r); });
  step(config.right_angles, "right_angles", [&] { return right_angles_of(r); });
  step(config.equal_sides, "equal_sides", [&] { return equal_sides_of(r); });
  const std::size_t before_axis = applied.size();
  step(config.axis, "axis", [&] { return axis_of(r); });
  if (applied.size() == before_axis) {
    step(config.parallel, "parallel", [&] { return parallel_of(r, neighbours); });
  }
  step(config.connection, "connection", [&] { return connection_of(r, neighbours); });
  return applied;
}

} // namespace penshape::recognize_detail
