#include "prepared_annulus.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "geometry/distance_kernel.hpp"

namespace penshape::annulus::detail {
namespace {

bool overlaps(const Box& a, const Box& b) {
  return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

Box shifted(Box b, PointD d) { return {b.x0 + d.x, b.y0 + d.y, b.x1 + d.x, b.y1 + d.y}; }

// Sutherland-Hodgman clip of a convex polygon by n . x <= h.
std::vector<PointD> clip(const std::vector<PointD>& poly, PointD n, double h) {
  std::vector<PointD> out;
  const std::size_t m = poly.size();
  for (std::size_t i = 0; i < m; ++i) {
    const PointD a = poly[i];
    const PointD b = poly[(i + 1) % m];
    const double sa = dot(n, a) - h;
    const double sb = dot(n, b) - h;
    if (sa <= 0.0) out.push_back(a);
    if ((sa < 0.0 && sb > 0.0) || (sa > 0.0 && sb < 0.0)) {
      const double t = sa / (sa - sb);
      out.push_back(a + (b - a) * t);
    }
  }
  return out;
}

double polygon_area2(const std::vector<PointD>& poly) {
  double s = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) s += cross(poly[i], poly[(i + 1) % poly.size()]);
  return s;
}

Curve polygon_curve(const std::vector<PointD>& poly) {
  Curve c;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    Piece p;
    p.a = poly[i];
    p.b = poly[(i + 1) % poly.size()];
    c.push_back(p);
  }
  return c;
}

Piece arc_piece(PointD center, double r, double phi0, double phi1) {
  return {.arc = true, .c = center, .r = r, .phi0 = phi0, .phi1 = phi1};
}

// Intersects every interval of `cur` with {A cos + B sin <= C}.
void intersect_trig(IntervalSet& cur, double A, double B, double C) {
  IntervalSet out;
  for (const Interval& iv : cur) trig_leq(A, B, C, iv.lo, iv.hi, out);
  cur.swap(out);
}

// --- segment pieces: z(u) = z0 + u w, u in [0, 1] ---

// u-interval of the segment inside {n . z <= h + off for every edge}; false if empty.
bool segment_in_halfplanes(const std::vector<Edge>& edges, double off, PointD z0, PointD w,
                           double& lo, double& hi) {
  lo = 0.0;
  hi = 1.0;
  for (const Edge& e : edges) {
    // The hole (off < 0) is open.
    clip_linear(lo, hi, dot(e.n, z0) - e.h - off, dot(e.n, w), off < 0.0);
    if (lo > hi) return false;
  }
  return true;
}

// u-interval of the segment inside the stadium of edge e (rectangle part and the disk at e.a).
void segment_in_stadium(const Edge& e, double delta, PointD z0, PointD w, IntervalSet& out) {
  double lo = 0.0;
  double hi = 1.0;
  const PointD r0 = z0 - e.a;
  clip_linear(lo, hi, -dot(r0, e.v), -dot(w, e.v));
  clip_linear(lo, hi, dot(r0, e.v) - e.len2, dot(w, e.v));
  clip_linear(lo, hi, dot(e.n, r0) - delta, dot(e.n, w));
  clip_linear(lo, hi, -dot(e.n, r0) - delta, -dot(e.n, w));
  if (lo <= hi) out.push_back({lo, hi});
  const double ww = dot(w, w);
  if (ww > 0.0) {
    double qlo = 0.0;
    double qhi = 1.0;
    if (quadratic_leq(ww, 2.0 * dot(w, r0), dot(r0, r0) - delta * delta, qlo, qhi)) {
      out.push_back({qlo, qhi});
    }
  } else if (dot(r0, r0) <= delta * delta) {
    out.push_back({0.0, 1.0});
  }
}

// --- arc pieces: z(phi) = z0 + r (cos phi, sin phi) ---

IntervalSet arc_in_halfplanes(const std::vector<Edge>& edges, double off, PointD z0, double r,
                              double lo, double hi) {
  IntervalSet cur{{lo, hi}};
  for (const Edge& e : edges) {
    intersect_trig(cur, r * e.n.x, r * e.n.y, e.h + off - dot(e.n, z0));
    if (cur.empty()) break;
  }
  return cur;
}

void arc_in_stadium(const Edge& e, double delta, PointD z0, double r, double lo, double hi,
                    IntervalSet& out) {
  const PointD r0 = z0 - e.a;
  IntervalSet cur{{lo, hi}};
  intersect_trig(cur, -r * e.v.x, -r * e.v.y, dot(r0, e.v));
  if (!cur.empty()) intersect_trig(cur, r * e.v.x, r * e.v.y, e.len2 - dot(r0, e.v));
  if (!cur.empty()) intersect_trig(cur, r * e.n.x, r * e.n.y, delta - dot(e.n, r0));
  if (!cur.empty()) intersect_trig(cur, -r * e.n.x, -r * e.n.y, delta + dot(e.n, r0));
  out.insert(out.end(), cur.begin(), cur.end());
  // |r0 + r u|^2 <= delta^2  <=>  2 r u . r0 <= delta^2 - r^2 - |r0|^2
  trig_leq(2.0 * r * r0.x, 2.0 * r * r0.y, delta * delta - r * r - dot(r0, r0), lo, hi, out);
}

} // namespace

PointD Piece::at(double t) const {
  if (arc) return {c.x + r * std::cos(t), c.y + r * std::sin(t)};
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

Box Piece::box() const {
  if (arc) return {c.x - r, c.y - r, c.x + r, c.y + r};
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
}

namespace {

// P's edges (with their unit outer normals and lines) and each edge's stadium box; returns the
// box of all stadiums.
Box add_edges(const std::vector<PointD>& v, double delta, PreparedAnnulus& an) {
  const std::size_t m = v.size();
  for (std::size_t k = 0; k < m; ++k) {
    Edge e;
    e.a = v[k];
    e.v = v[(k + 1) % m] - v[k];
    e.len2 = dot(e.v, e.v);
    const double len = std::sqrt(e.len2);
    e.n = {e.v.y / len, -e.v.x / len};
    e.h = dot(e.n, e.a);
    an.edges.push_back(e);
    const PointD b = v[(k + 1) % m];
    an.stadium_boxes.push_back({std::min(e.a.x, b.x) - delta, std::min(e.a.y, b.y) - delta,
                                std::max(e.a.x, b.x) + delta, std::max(e.a.y, b.y) + delta});
  }
  Box box = an.stadium_boxes.front();
  for (const Box& b : an.stadium_boxes) {
    box = {std::min(box.x0, b.x0), std::min(box.y0, b.y0), std::max(box.x1, b.x1),
           std::max(box.y1, b.y1)};
  }
  return box;
}

// Every piece of every stadium boundary: a superset of the annulus boundary (Section 5).
void add_stadium_pieces(double delta, PreparedAnnulus& an) {
  for (const Edge& e : an.edges) {
    const PointD b = e.a + e.v;
    for (double side : {1.0, -1.0}) {
      Piece s;
      s.a = e.a + e.n * (side * delta);
      s.b = b + e.n * (side * delta);
      an.outer_curve.push_back(s);
      if (delta == 0.0) break;
    }
    if (delta > 0.0) {
      an.outer_curve.push_back(arc_piece(e.a, delta, -std::numbers::pi, std::numbers::pi));
    }
  }
}

// Inner offset: P clipped by every edge line moved inwards by delta (kept when not degenerate).
void add_inner_offset(const std::vector<PointD>& v, double delta, PreparedAnnulus& an) {
  std::vector<PointD> inner = v;
  for (const Edge& e : an.edges) {
    inner = clip(inner, e.n, e.h - delta);
    if (inner.size() < 3) break;
  }
  double extent = 0.0;
  for (const PointD& q : v) extent = std::max({extent, std::abs(q.x), std::abs(q.y)});
  if (inner.size() >= 3 && polygon_area2(inner) > 1e-24 * extent * extent) {
    an.inner = inner;
    an.inner_curve = polygon_curve(inner);
  }
}

// The exact outer offset's boundary: each edge moved outwards by delta, and the arc of radius
// delta at each vertex between consecutive edges' normals.
void add_round_outer(double delta, PreparedAnnulus& an) {
  const std::size_t m = an.edges.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Edge& e = an.edges[k];
    const Edge& next = an.edges[(k + 1) % m];
    Piece s;
    s.a = e.a + e.n * delta;
    s.b = (e.a + e.v) + e.n * delta;
    an.outer_curve.push_back(s);
    if (delta > 0.0) {
      const double phi0 = std::atan2(e.n.y, e.n.x);
      double phi1 = std::atan2(next.n.y, next.n.x);
      if (phi1 < phi0) phi1 += 2.0 * std::numbers::pi;
      an.outer_curve.push_back(arc_piece(next.a, delta, phi0, phi1));
    }
  }
}

PreparedAnnulus prepare_single(const TemplatePolygon& p, OuterOffset outer, double delta) {
  PreparedAnnulus an;
  an.convex = p.convex();
  an.outer = outer;
  an.delta = delta;
  const auto& v = p.vertices();
  const std::size_t m = v.size();
  an.box = add_edges(v, delta, an);
  if (!p.convex()) {
    add_stadium_pieces(delta, an);
    an.outer_stride = 2.0;
    return an;
  }
  add_inner_offset(v, delta, an);
  // Linearized outer offset: consecutive edge lines moved outwards by delta meet at a miter.
  for (std::size_t k = 0; k < m; ++k) {
    const Edge& prev = an.edges[(k + m - 1) % m];
    const Edge& cur = an.edges[k];
    const double s = delta / (1.0 + dot(prev.n, cur.n));
    an.outer_poly.push_back(v[k] + (prev.n + cur.n) * s);
  }
  if (outer != OuterOffset::kLinearized) {
    add_round_outer(delta, an);
    return an;
  }
  an.outer_curve = polygon_curve(an.outer_poly);
  an.box = bounding_box(an.outer_poly);
  return an;
}
} // namespace

PreparedAnnulus prepare(const TemplatePolygon& p, OuterOffset outer, double delta,
                        double curve_delta) {
  PreparedAnnulus an = prepare_single(p, outer, delta);
  an.has_hole = !an.inner.empty();
  if (an.has_hole) {
    // Vertex centroid of the hole and its distance to the nearest hole edge line, shrunk a
    // little so rounding cannot put the disk outside the open hole.
    PointD c{0.0, 0.0};
    for (const PointD& q : an.inner) c = c + q;
    c = c * (1.0 / static_cast<double>(an.inner.size()));
    double r = INFINITY;
    for (const Edge& e : an.edges) r = std::min(r, e.h - delta - dot(e.n, c));
    an.hole_centre = c;
    an.hole_radius = r > 0.0 ? r * (1.0 - 1e-9) : 0.0;
  }
  if (curve_delta != delta) {
    PreparedAnnulus c = prepare_single(p, outer, curve_delta);
    an.inner = std::move(c.inner);
    an.outer_poly = std::move(c.outer_poly);
    an.inner_curve = std::move(c.inner_curve);
    an.outer_curve = std::move(c.outer_curve);
  }
  return an;
}

PreparedAnnulus prepare(const TemplatePolygon& p, OuterOffset outer, double delta) {
  return prepare(p, outer, delta, delta);
}

namespace {

// Every corner of the piece's box inside the hole's disk: the piece is inside the open hole.
bool inside_hole_disk(const PreparedAnnulus& an, const Box& pb) {
  if (an.hole_radius <= 0.0) return false;
  const double r2 = an.hole_radius * an.hole_radius;
  for (double x : {pb.x0, pb.x1}) {
    for (double y : {pb.y0, pb.y1}) {
      const double dx = x - an.hole_centre.x;
      const double dy = y - an.hole_centre.y;
      if (!(dx * dx + dy * dy < r2)) return false;
    }
  }
  return true;
}

// Lipschitz filter: the annulus measure is 1-Lipschitz and every point of the piece is within
// `reach` of its middle, so a middle far inside or far outside decides the whole piece.
std::optional<IntervalSet> decided_by_middle(const PreparedAnnulus& an, const Piece& piece,
                                             PointD d) {
  const double mid_t = 0.5 * (piece.lo() + piece.hi());
  const PointD z = piece.at(mid_t) + d;
  const double reach = piece.arc ? piece.r * 0.5 * (piece.phi1 - piece.phi0)
                                 : 0.5 * std::sqrt(dot(piece.b - piece.a, piece.b - piece.a));
  const double m = prepared_measure(an, z);
  const double slack = 1e-12 * (std::abs(z.x) + std::abs(z.y) + reach + an.delta) + 1e-300;
  if (m + reach < an.delta - slack) return IntervalSet{{piece.lo(), piece.hi()}};
  if (m - reach > an.delta + slack) return IntervalSet{};
  return std::nullopt;
}

// A convex annulus's outer offset on the segment z0 + t w: one interval [lo, hi], or false.
bool segment_in_convex_outer(const PreparedAnnulus& an, const Box& pb, PointD z0, PointD w,
                             double& lo, double& hi) {
  if (an.outer == OuterOffset::kLinearized) {
    return segment_in_halfplanes(an.edges, an.delta, z0, w, lo, hi);
  }
  // P + disk(delta) is convex, so its trace on the segment is one interval: the hull of the
  // traces of P and of the stadiums that make it up.
  IntervalSet parts;
  if (segment_in_halfplanes(an.edges, 0.0, z0, w, lo, hi)) parts.push_back({lo, hi});
  for (std::size_t k = 0; k < an.edges.size(); ++k) {
    if (overlaps(pb, an.stadium_boxes[k])) segment_in_stadium(an.edges[k], an.delta, z0, w, parts);
  }
  if (parts.empty()) return false;
  lo = parts.front().lo;
  hi = parts.front().hi;
  for (const Interval& iv : parts) {
    lo = std::min(lo, iv.lo);
    hi = std::max(hi, iv.hi);
  }
  return true;
}

IntervalSet segment_members(const PreparedAnnulus& an, const Piece& piece, PointD d,
                            const Box& pb) {
  IntervalSet result;
  const PointD z0 = piece.a + d;
  const PointD w = piece.b - piece.a;
  if (!an.convex) {
    for (std::size_t k = 0; k < an.edges.size(); ++k) {
      if (overlaps(pb, an.stadium_boxes[k]))
        segment_in_stadium(an.edges[k], an.delta, z0, w, result);
    }
    normalize(result);
    return result;
  }
  double lo = 0.0;
  double hi = 0.0;
  if (!segment_in_convex_outer(an, pb, z0, w, lo, hi)) return result;
  result.push_back({lo, hi});
  double ilo = 0.0;
  double ihi = 0.0;
  if (an.has_hole && segment_in_halfplanes(an.edges, -an.delta, z0, w, ilo, ihi)) {
    // Ends clamped by the piece are not boundaries of the open hole: extend them past it.
    result =
        subtract_interior(result, IntervalSet{{ilo <= 0.0 ? -1.0 : ilo, ihi >= 1.0 ? 2.0 : ihi}});
  }
  return result;
}

IntervalSet arc_members(const PreparedAnnulus& an, const Piece& piece, PointD d, const Box& pb) {
  IntervalSet result;
  const PointD z0 = piece.c + d;
  const double r = piece.r;
  const double delta = an.delta;
  if (!an.convex) {
    for (std::size_t k = 0; k < an.edges.size(); ++k) {
      if (overlaps(pb, an.stadium_boxes[k])) {
        arc_in_stadium(an.edges[k], delta, z0, r, piece.phi0, piece.phi1, result);
      }
    }
    normalize(result);
    return result;
  }
  if (an.outer == OuterOffset::kLinearized) {
    result = arc_in_halfplanes(an.edges, delta, z0, r, piece.phi0, piece.phi1);
  } else {
    result = arc_in_halfplanes(an.edges, 0.0, z0, r, piece.phi0, piece.phi1);
    for (std::size_t k = 0; k < an.edges.size(); ++k) {
      if (overlaps(pb, an.stadium_boxes[k])) {
        arc_in_stadium(an.edges[k], delta, z0, r, piece.phi0, piece.phi1, result);
      }
    }
    normalize(result);
  }
  if (!result.empty() && an.has_hole) {
    IntervalSet hole = arc_in_halfplanes(an.edges, -delta, z0, r, piece.phi0, piece.phi1);
    if (!hole.empty()) {
      if (hole.front().lo <= piece.phi0) hole.front().lo = piece.phi0 - 1.0;
      if (hole.back().hi >= piece.phi1) hole.back().hi = piece.phi1 + 1.0;
      result = subtract_interior(result, hole);
    }
  }
  return result;
}

} // namespace

IntervalSet member_set(const PreparedAnnulus& an, const Piece& piece, PointD d) {
  const Box pb = shifted(piece.box(), d);
  if (!overlaps(pb, an.box) || inside_hole_disk(an, pb)) return {};
  if (std::optional<IntervalSet> decided = decided_by_middle(an, piece, d)) return *decided;
  return piece.arc ? arc_members(an, piece, d, pb) : segment_members(an, piece, d, pb);
}

double annulus_measure(const TemplatePolygon& p, OuterOffset outer, PointD x) {
  const auto& v = p.vertices();
  const std::size_t m = v.size();
  double fmax = -INFINITY; // max signed distance to the edge lines (convex)
  double dmin2 = INFINITY; // squared distance to the boundary
  for (std::size_t k = 0; k < m; ++k) {
    const PointD a = v[k];
    const PointD b = v[(k + 1) % m];
    const PointD e = b - a;
    const PointD r = x - a;
    if (p.convex()) fmax = std::max(fmax, -cross(e, r) / std::sqrt(dot(e, e)));
    const PointD q = r - e * ::penshape::detail::proposed_foot_parameter(x, a, b);
    dmin2 = std::min(dmin2, dot(q, q));
  }
  if (!p.convex()) return std::sqrt(dmin2);
  if (fmax <= 0.0) return -fmax; // inside: distance to the nearest edge line
  return outer == OuterOffset::kLinearized ? fmax : std::sqrt(dmin2);
}

double prepared_measure(const PreparedAnnulus& an, PointD x) {
  double fmax = -INFINITY;
  for (const Edge& e : an.edges) fmax = std::max(fmax, dot(e.n, x) - e.h);
  if (an.convex && fmax <= 0.0) return -fmax;
  if (an.convex && an.outer == OuterOffset::kLinearized) return fmax;
  double dmin2 = INFINITY;
  for (const Edge& e : an.edges) {
    const PointD r = x - e.a;
    const PointD q = r - e.v * ::penshape::detail::proposed_foot_parameter_along(r, e.v, e.len2);
    dmin2 = std::min(dmin2, dot(q, q));
  }
  return std::sqrt(dmin2);
}

PointD curve_point(const Curve& c, double g, double stride) {
  double idx = std::floor(g / stride);
  idx = std::clamp(idx, 0.0, static_cast<double>(c.size() - 1));
  const Piece& p = c[static_cast<std::size_t>(idx)];
  const double f = std::clamp(g - idx * stride, 0.0, 1.0);
  return p.at(p.lo() + f * (p.hi() - p.lo()));
}

} // namespace penshape::annulus::detail
