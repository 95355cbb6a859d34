// Straight families: the segment, open polylines and closed polygons (triangle, quadrilateral,
// polygon of 5..8 corners).
// Corners come from the dynamic-programming partition; each side is then re-fitted as a
// total-least-squares line over the middle of its points (hand-drawn corners are rounded, the
// sides' lines meet where the intended corner was), and the vertices are refined by minimax.
#include <cmath>

#include "recognize/fitting/fit.hpp"

namespace penshape::recognize_detail {
namespace {

// Line through the middle part of pts[a..b] (indices cyclic modulo pts.size()).
Line side_line(const std::vector<PointD>& pts, std::size_t a, std::size_t b, bool trim_a,
               bool trim_b) {
  const std::size_t n = pts.size();
  const std::size_t count = (b + n - a) % n + 1;
  const std::size_t trim = count / 6;
  std::vector<PointD> side;
  for (std::size_t i = trim_a ? trim : 0; i + (trim_b ? trim : 0) < count; ++i) {
    side.push_back(pts[(a + i) % n]);
  }
  if (side.size() < 2) side = {pts[a], pts[b % n]};
  return fit_line(side);
}

PointD project(PointD p, const Line& l) {
  return l.point + dot(p - l.point, l.direction) * l.direction;
}

// Vertex i where lines i-1 and i meet; the DP corner when they are (nearly) parallel or meet
// absurdly far away.
PointD meet(const Line& a, const Line& b, PointD fallback, double size) {
  PointD x;
  if (!line_intersection(a.point, a.direction, b.point, b.direction, x)) return fallback;
  return distance(x, fallback) > 0.5 * size ? fallback : x;
}

std::vector<double> flatten(const std::vector<PointD>& v) {
  std::vector<double> out;
  for (const PointD& p : v) {
    out.push_back(p.x);
    out.push_back(p.y);
  }
  return out;
}

std::vector<PointD> unflatten(const std::vector<double>& v) {
  std::vector<PointD> out;
  for (std::size_t i = 0; i + 1 < v.size(); i += 2) out.push_back({v[i], v[i + 1]});
  return out;
}

// The mean of a polygon's vertices (its parameters' centre).
PointD vertex_centroid(const std::vector<PointD>& vertices) {
  PointD c;
  for (const PointD& v : vertices) c = c + v;
  return (1.0 / static_cast<double>(vertices.size())) * c;
}

Fit finish(const PreparedStroke& s, ShapeClass shape, const std::vector<PointD>& vertices,
           bool closed) {
  const ShapeBuilder build = [closed](const std::vector<double>& p) -> std::optional<CleanShape> {
    CleanShape c;
    c.path = unflatten(p);
    if (closed) c.path.push_back(c.path.front());
    return c;
  };
  const Refinement r = refine_minimax(s, flatten(vertices), build, 0.02 * s.size, true);
  Fit fit;
  fit.shape = shape;
  fit.clean = *build(r.params);
  fit.fit_error = r.objective;
  fit.params.vertices = unflatten(r.params);
  fit.params.center = vertex_centroid(fit.params.vertices);
  return fit;
}

// Whether the closed polygon turns the same way at every vertex.
bool convex_turns(const std::vector<PointD>& v) {
  bool left = false, right = false;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const PointD a = v[(i + v.size() - 1) % v.size()];
    const double c = cross(v[i] - a, v[(i + 1) % v.size()] - v[i]);
    left = left || c > 0.0;
    right = right || c < 0.0;
  }
  return !(left && right);
}

// The closed polygon on these vertices as it is, with the refinement's objective as its error.
Fit unrefined_polygon(const PreparedStroke& s, const std::vector<PointD>& vertices) {
  Fit fit;
  fit.shape = polygon_class(vertices.size());
  fit.params.vertices = vertices;
  fit.clean.path = vertices;
  fit.clean.path.push_back(vertices.front());
  fit.fit_error = fit_objective(s, fit.clean, true);
  fit.params.center = vertex_centroid(vertices);
  return fit;
}

} // namespace

ShapeClass polygon_class(std::size_t corners) {
  if (corners == 3) return ShapeClass::kTriangle;
  return corners == 4 ? ShapeClass::kQuadrilateral : ShapeClass::kPolygon;
}

std::optional<Fit> fit_segment(const PreparedStroke& s) {
  const Line l = fit_line(s.fit_points);
  double lo = INFINITY, hi = -INFINITY;
  for (const PointD& p : s.fit_points) {
    const double t = dot(p - l.point, l.direction);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  return finish(s, ShapeClass::kSegment, {l.point + lo * l.direction, l.point + hi * l.direction},
                false);
}

std::optional<Fit> fit_polyline(const PreparedStroke& s, std::size_t segments) {
  const std::vector<std::size_t> idx = open_corners(s.fit_points, segments + 1);
  if (idx.size() != segments + 1) return std::nullopt;
  std::vector<Line> lines;
  for (std::size_t i = 0; i < segments; ++i) {
    lines.push_back(side_line(s.fit_points, idx[i], idx[i + 1], i > 0, i + 1 < segments));
  }
  std::vector<PointD> v;
  v.push_back(project(s.fit_points.front(), lines.front()));
  for (std::size_t i = 1; i < segments; ++i) {
    v.push_back(meet(lines[i - 1], lines[i], s.fit_points[idx[i]], s.size));
  }
  v.push_back(project(s.fit_points.back(), lines.back()));
  return finish(s, ShapeClass::kPolyline, v, false);
}

std::optional<Fit> fit_polygon(const PreparedStroke& s, std::size_t corners) {
  const std::vector<std::size_t>& idx = closed_corners(s, corners);
  if (idx.size() != corners) return std::nullopt;
  std::vector<Line> lines;
  for (std::size_t i = 0; i < corners; ++i) {
    lines.push_back(side_line(s.fit_points, idx[i], idx[(i + 1) % corners], true, true));
  }
  std::vector<PointD> v;
  for (std::size_t i = 0; i < corners; ++i) {
    v.push_back(meet(lines[(i + corners - 1) % corners], lines[i], s.fit_points[idx[i]], s.size));
  }
  return finish(s, polygon_class(corners), v, true);
}

std::optional<Fit> fit_polygon_from_corners(const PreparedStroke& s,
                                            const std::vector<PointD>& corners) {
  if (corners.size() < 3) return std::nullopt;
  return finish(s, polygon_class(corners.size()), corners, true);
}

std::optional<Fit> fit_polygon_at_turns(const PreparedStroke& s,
                                        const std::vector<PointD>& corners) {
  if (corners.size() < 3 || !convex_turns(corners)) return std::nullopt;
  return unrefined_polygon(s, corners);
}

std::optional<Fit> fit_polygon_through_turns(const PreparedStroke& s,
                                             const std::vector<PointD>& corners) {
  const std::size_t k = corners.size();
  if (k < 3 || s.fit_points.size() < 2 * k) return std::nullopt;
  std::vector<std::size_t> idx;
  for (const PointD& c : corners) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < s.fit_points.size(); ++i) {
      if (distance(s.fit_points[i], c) < distance(s.fit_points[best], c)) best = i;
    }
    idx.push_back(best);
  }
  for (std::size_t i = 1; i < k; ++i) {
    if (idx[i] <= idx[i - 1]) return std::nullopt; // not in the stroke's order
  }
  std::vector<Line> lines;
  for (std::size_t i = 0; i < k; ++i) {
    lines.push_back(side_line(s.fit_points, idx[i], idx[(i + 1) % k], true, true));
  }
  std::vector<PointD> v;
  for (std::size_t i = 0; i < k; ++i) {
    v.push_back(meet(lines[(i + k - 1) % k], lines[i], corners[i], s.size));
  }
  return unrefined_polygon(s, v);
}

} // namespace penshape::recognize_detail
