// Live candidates (see live_candidate.hpp).
#include "recognize/live/live_candidate.hpp"

#include <cmath>
#include <numbers>

#include "recognize/classify/sharp_polygon.hpp"

namespace penshape::recognize_detail {
namespace {

// Moves the end b of the segment [a, b] along its line to p's projection when p lies within
// epsilon of the line beyond b.
bool extend_segment(PointD a, PointD& b, PointD p, double epsilon) {
  const PointD ab = b - a;
  const double len = norm(ab);
  if (len <= 0.0) return false;
  const PointD u = (1.0 / len) * ab;
  const double t = dot(p - a, u);
  if (t <= len || std::abs(cross(u, p - a)) > epsilon) return false;
  b = a + t * u;
  return true;
}

// Extends the arc's sweep to p's angle when p lies within epsilon of its circle, beyond the
// arc's end in the arc's direction, and the arc stays below a full turn.
bool extend_arc(Fit& f, PointD p, double epsilon) {
  CleanShape& c = f.clean;
  if (std::abs(distance(p, c.center) - c.rx) > epsilon) return false;
  const double end = c.t0 + c.sweep;
  const double delta =
      std::remainder(std::atan2(p.y - c.center.y, p.x - c.center.x) - end, 2 * std::numbers::pi);
  if (delta * c.sweep <= 0.0 || std::abs(c.sweep + delta) >= 2 * std::numbers::pi) return false;
  c.sweep += delta;
  f.params.sweep_angle = c.sweep;
  if (f.params.vertices.size() == 2) f.params.vertices[1] = c.at(c.t0 + c.sweep);
  return true;
}

} // namespace

LiveCandidate LiveCandidate::make(Scored&& scored, const PreparedStroke& s, double epsilon,
                                  double coordinate_magnitude, bool grow_open) {
  LiveCandidate c;
  c.grow_open = grow_open;
  c.rank = scored.rank;
  c.epsilon = epsilon;
  c.family = family_of(scored.fit);
  c.sharp_polygon = recognize_detail::sharp_polygon(s, scored.fit);
  c.yields_to_sharp_polygon = recognize_detail::yields_to_sharp_polygon(s, scored.fit);
  c.fit_measure = recognize_detail::fit_measure(scored.candidate);
  if (convex_polygon(scored.fit.shape)) {
    try {
      const annulus::TemplatePolygon t = annulus::make_convex_template(scored.fit.params.vertices);
      c.online.emplace(t, annulus::OuterOffset::kRound, epsilon, coordinate_magnitude);
      // Seeded with every other fit point along the stroke at the fit (ends kept; they pin the
      // translation as well for a preview at half the structures' cost, and the certificate
      // already covers the fitted path), as one batch (one witness search), then fed every
      // later point. finish() certifies against every sample anyway.
      std::vector<PointD> seeds;
      for (std::size_t i = 0; i < s.fit_points.size(); i += 2) seeds.push_back(s.fit_points[i]);
      if (!(seeds.back() == s.fit_points.back())) seeds.push_back(s.fit_points.back());
      c.online->add_all(seeds);
      c.alive = c.online->answer() != Answer::kNo; // a certified fit cannot be a NO
    } catch (const InvalidInput&) {
      c.online.reset(); // a degenerate template: fall back to the fixed placement
    }
  }
  c.fit = std::move(scored.fit);
  return c;
}

bool LiveCandidate::accept(PointD p) {
  if (!alive) return false;
  if (online) {
    alive = online->add(p) != Answer::kNo;
    return alive;
  }
  if (fit.clean.distance_to(p) <= epsilon) return true;
  if (!grow_open) return alive = false;
  bool grew = false;
  switch (fit.shape) {
    case ShapeClass::kSegment:
    case ShapeClass::kPolyline: {
      std::vector<PointD>& path = fit.clean.path;
      if (path.size() < 2 || fit.params.vertices.size() != path.size()) break;
      // A polyline grows at its last vertex (its vertices follow the pen); a segment's ends
      // are ordered along its line, so the pen may be moving past either.
      grew = extend_segment(path[path.size() - 2], path.back(), p, epsilon) ||
             (fit.shape == ShapeClass::kSegment && extend_segment(path[1], path[0], p, epsilon));
      if (grew) {
        fit.params.vertices = path;
        PointD c;
        for (const PointD& v : path) c = c + v;
        fit.params.center = (1.0 / static_cast<double>(path.size())) * c;
      }
      break;
    }
    case ShapeClass::kArc:
      grew = extend_arc(fit, p, epsilon);
      break;
    default:
      break;
  }
  if (grew) ++version;
  alive = grew;
  return alive;
}

bool LiveCandidate::accept_all(std::span<const PointD> points) {
  if (online) {
    if (alive && !points.empty()) alive = online->add_all(points) != Answer::kNo;
    return alive;
  }
  for (const PointD& p : points) {
    if (!accept(p)) return false;
  }
  return alive;
}

PointD LiveCandidate::shift() const {
  if (!online || online->answer() != Answer::kYes) return {};
  return {online->placement().tx, online->placement().ty};
}

Fit LiveCandidate::placed() const {
  Fit f = fit;
  if (!online || online->answer() != Answer::kYes) return f;
  const PointD t = shift();
  for (PointD& v : f.clean.path) v = v + t;
  for (PointD& v : f.params.vertices) v = v + t;
  f.params.center = f.params.center + t;
  return f;
}

} // namespace penshape::recognize_detail
