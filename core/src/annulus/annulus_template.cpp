// Template validation, exact containment (the certificate) and the width measure.
#include "penshape/core/annulus/annulus_template.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "geometry/exact_predicates.hpp"
#include "geometry/segment_sweep.hpp"
#include "prepared_annulus.hpp"

namespace penshape::annulus {
namespace {

using ::penshape::detail::orientation;

void check_coordinate(double v, const Limits& limits, const std::string& what) {
  if (!std::isfinite(v)) throw InvalidInput(what + " is not finite");
  if (std::abs(v) > limits.max_abs_coordinate) {
    throw InvalidInput(what + " exceeds the coordinate limit " +
                       std::to_string(limits.max_abs_coordinate));
  }
}

// What templates and point sets share: at most `max` points ("<set> has N <plural>, limit M")
// and every coordinate within the limit ("<one> i x ...").
void check_points(const std::vector<PointD>& v, std::size_t max, const Limits& limits,
                  const char* set, const char* plural, const char* one) {
  if (v.size() > max) {
    throw InvalidInput(std::string(set) + " has " + std::to_string(v.size()) + " " + plural +
                       ", limit " + std::to_string(max));
  }
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string name = std::string(one) + ' ' + std::to_string(i);
    check_coordinate(v[i].x, limits, name + " x");
    check_coordinate(v[i].y, limits, name + " y");
  }
}

// Shared checks; orients counterclockwise (exact signed area sign).
void check_ring(std::vector<PointD>& v, const Limits& limits) {
  if (v.size() < 3) throw InvalidInput("template needs at least 3 vertices");
  check_points(v, limits.max_template_vertices, limits, "template", "vertices", "template vertex");
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i] == v[(i + 1) % v.size()]) {
      throw InvalidInput("template vertices " + std::to_string(i) + " and " +
                         std::to_string((i + 1) % v.size()) + " are equal");
    }
  }
  Rational area2 = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const ExactPoint a = exact(v[i]);
    const ExactPoint b = exact(v[(i + 1) % v.size()]);
    area2 += a.x * b.y - a.y * b.x;
  }
  if (sgn(area2) == 0) throw InvalidInput("template has zero area");
  if (sgn(area2) < 0) std::reverse(v.begin(), v.end());
}

void check_simple(const std::vector<PointD>& v) {
  const std::size_t m = v.size();
  for (std::size_t i = 0; i < m; ++i) {
    const PointD a = v[i];
    const PointD b = v[(i + 1) % m];
    // Adjacent edge: must not fold back onto this one.
    const PointD c = v[(i + 2) % m];
    if (orientation(a, b, c) == 0 && (a.x - b.x) * (c.x - b.x) + (a.y - b.y) * (c.y - b.y) > 0) {
      throw InvalidInput("template edges " + std::to_string(i) + " and " +
                         std::to_string((i + 1) % m) + " overlap");
    }
  }
  // Other edge pairs may not meet at all: the kernel's sweep, as for input regions.
  std::vector<ExactPoint> exact_v;
  exact_v.reserve(m);
  for (const PointD& p : v) exact_v.push_back(exact(p));
  std::vector<::penshape::detail::FilteredPoint> points;
  points.reserve(m);
  for (const ExactPoint& p : exact_v) points.push_back(::penshape::detail::filtered(p));
  const std::vector<std::span<const ::penshape::detail::FilteredPoint>> ring{points};
  if (const auto pair = ::penshape::detail::find_ring_contact(ring)) {
    throw InvalidInput("template is not simple: edges " + std::to_string(pair->first.index) +
                       " and " + std::to_string(pair->second.index) + " intersect");
  }
}

struct ExactFrame {
  Rational c, s, tx, ty;
  explicit ExactFrame(const Placement& pl) : tx(exact(pl.tx)), ty(exact(pl.ty)) {
    const Rational u = exact(pl.tan_half_theta);
    const Rational den = 1 + u * u;
    c = (1 - u * u) / den;
    s = 2 * u / den;
  }
  [[nodiscard]] ExactPoint to_template(PointD q) const {
    const Rational dx = exact(q.x) - tx;
    const Rational dy = exact(q.y) - ty;
    return {c * dx + s * dy, c * dy - s * dx};
  }
};

PointD to_template_double(const Placement& pl, PointD q) {
  const double u = pl.tan_half_theta;
  const double den = 1.0 + u * u;
  const double c = (1.0 - u * u) / den;
  const double s = 2.0 * u / den;
  const double dx = q.x - pl.tx;
  const double dy = q.y - pl.ty;
  return {c * dx + s * dy, c * dy - s * dx};
}

bool contains_rational(const TemplatePolygon& p, OuterOffset outer, double delta,
                       const ExactPoint& x) {
  const auto& v = p.vertices();
  const std::size_t m = v.size();
  const Rational d2 = exact(delta) * exact(delta);
  bool inside = true;            // every cross >= 0
  bool outer_lin_ok = true;      // linearized outer: every cross >= -delta |e|
  bool near_line_inside = false; // some cross <= delta |e| (not deeper than delta)
  bool near_boundary = false;    // distance to some edge segment <= delta
  for (std::size_t k = 0; k < m; ++k) {
    const ExactPoint a = exact(v[k]);
    const ExactPoint b = exact(v[(k + 1) % m]);
    const Rational ex = b.x - a.x;
    const Rational ey = b.y - a.y;
    const Rational rx = x.x - a.x;
    const Rational ry = x.y - a.y;
    const Rational len2 = ex * ex + ey * ey;
    const Rational cr = ex * ry - ey * rx;
    const bool close_to_line = cr * cr <= d2 * len2;
    if (sgn(cr) < 0) {
      inside = false;
      if (!close_to_line) outer_lin_ok = false;
    }
    if (sgn(cr) <= 0 || close_to_line) near_line_inside = true;
    if (!near_boundary) {
      const Rational t = rx * ex + ry * ey;
      Rational dist2;
      if (sgn(t) <= 0) {
        dist2 = rx * rx + ry * ry;
      } else if (t >= len2) {
        const Rational qx = x.x - b.x;
        const Rational qy = x.y - b.y;
        dist2 = qx * qx + qy * qy;
      } else {
        dist2 = cr * cr / len2;
      }
      if (dist2 <= d2) near_boundary = true;
    }
  }
  if (!p.convex()) return near_boundary;
  if (outer == OuterOffset::kLinearized) return outer_lin_ok && near_line_inside;
  return inside ? near_line_inside : near_boundary;
}

double magnitude(const std::vector<PointD>& pts) {
  double m = 0.0;
  for (const PointD& q : pts) m = std::max({m, std::abs(q.x), std::abs(q.y)});
  return m;
}

} // namespace

const char* to_string(OuterOffset o) { return o == OuterOffset::kRound ? "round" : "linearized"; }

TemplatePolygon make_convex_template(std::vector<PointD> vertices, const Limits& limits) {
  check_ring(vertices, limits);
  const std::size_t m = vertices.size();
  for (std::size_t i = 0; i < m; ++i) {
    const int o = orientation(vertices[(i + m - 1) % m], vertices[i], vertices[(i + 1) % m]);
    if (o == 0) {
      throw InvalidInput("template vertex " + std::to_string(i) +
                         " is collinear with its neighbours");
    }
    if (o < 0) {
      throw InvalidInput("template vertex " + std::to_string(i) +
                         " is reflex: the template is not convex");
    }
  }
  // All left turns still allow a polygon that winds twice (a star): reject self-intersections.
  check_simple(vertices);
  TemplatePolygon t;
  t.vertices_ = std::move(vertices);
  t.convex_ = true;
  return t;
}

TemplatePolygon make_simple_template(std::vector<PointD> vertices, const Limits& limits) {
  check_ring(vertices, limits);
  check_simple(vertices);
  TemplatePolygon t;
  t.vertices_ = std::move(vertices);
  t.convex_ = false;
  return t;
}

void validate_points(const std::vector<PointD>& points, const Limits& limits) {
  if (points.empty()) throw InvalidInput("point set is empty");
  check_points(points, limits.max_points, limits, "point set", "points", "point");
}

void validate_delta(double delta, const Limits& limits) {
  check_coordinate(delta, limits, "delta");
  if (delta < 0.0) throw InvalidInput("delta is negative");
}

bool annulus_contains_exactly(const TemplatePolygon& p, OuterOffset outer, double delta,
                              const Placement& placement, PointD q) {
  return contains_rational(p, outer, delta, ExactFrame(placement).to_template(q));
}

std::vector<std::size_t> covered_exactly(const TemplatePolygon& p, OuterOffset outer, double delta,
                                         const Placement& placement,
                                         const std::vector<PointD>& points) {
  const ExactFrame frame(placement);
  double extent = 0.0;
  for (const PointD& v : p.vertices()) extent = std::max({extent, std::abs(v.x), std::abs(v.y)});
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    // Filter: the double measure decides unless it is within a generous rounding bound.
    const PointD x = to_template_double(placement, points[i]);
    const double measure = detail::annulus_measure(p, outer, x);
    const double slack = 1e-9 * (extent + delta + std::abs(points[i].x) + std::abs(points[i].y) +
                                 std::abs(placement.tx) + std::abs(placement.ty));
    bool in = false;
    if (measure < delta - slack) {
      in = true;
    } else if (measure <= delta + slack) {
      in = contains_rational(p, outer, delta, frame.to_template(points[i]));
    }
    if (in) out.push_back(i);
  }
  return out;
}

double width_at(const TemplatePolygon& p, OuterOffset outer, const Placement& placement,
                const std::vector<PointD>& points) {
  double w = 0.0;
  for (const PointD& q : points) {
    w = std::max(w, detail::annulus_measure(p, outer, to_template_double(placement, q)));
  }
  return w;
}

double annulus_margin(const TemplatePolygon& p, double delta, const std::vector<PointD>& points) {
  return 1e-10 * (magnitude(p.vertices()) + delta + magnitude(points));
}

} // namespace penshape::annulus
