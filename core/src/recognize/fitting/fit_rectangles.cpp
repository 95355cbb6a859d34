// Rectangle, square and diamond: constrained quadrilaterals, seeded from the free
// quadrilateral's corners and refined by minimax over their few parameters.
#include <cmath>
#include <numbers>

#include "recognize/fitting/fit.hpp"

namespace penshape::recognize_detail {
namespace {

std::vector<PointD> rectangle_corners(PointD c, double w, double h, double theta) {
  const PointD u{std::cos(theta), std::sin(theta)};
  const PointD v{-u.y, u.x};
  const PointD a = (w / 2) * u;
  const PointD b = (h / 2) * v;
  return {c - a - b, c + a - b, c + a + b, c - a + b};
}

Fit make_fit(ShapeClass shape, const std::vector<PointD>& corners, double objective, PointD c,
             double rotation) {
  Fit f;
  f.shape = shape;
  f.clean.path = closed_ring(corners);
  f.fit_error = objective;
  f.params.vertices = corners;
  f.params.center = c;
  f.params.rotation = rotation;
  return f;
}

// Orientation in (-pi/4, pi/4] with the extents swapped to match.
void normalise(double& theta, double& w, double& h) {
  constexpr double kQuarter = std::numbers::pi / 2;
  while (theta > kQuarter / 2) {
    theta -= kQuarter;
    std::swap(w, h);
  }
  while (theta <= -kQuarter / 2) {
    theta += kQuarter;
    std::swap(w, h);
  }
}

// A first rectangle for the quadrilateral q: orientation from its sides averaged modulo 90
// degrees (angles times four, by length), extents and centre from its corners along those axes.
struct RectangleStart {
  PointD centre;
  double w = 0.0, h = 0.0, theta = 0.0;
};

RectangleStart rectangle_start(const std::vector<PointD>& q, PointD c0) {
  PointD acc;
  for (std::size_t i = 0; i < 4; ++i) {
    const PointD d = q[(i + 1) % 4] - q[i];
    const double a = std::atan2(d.y, d.x);
    const double len = norm(d);
    acc = acc + PointD{len * std::cos(4 * a), len * std::sin(4 * a)};
  }
  const double theta0 = std::atan2(acc.y, acc.x) / 4;
  const PointD u{std::cos(theta0), std::sin(theta0)};
  const PointD v{-u.y, u.x};
  std::vector<double> us, vs;
  for (const PointD& p : q) {
    us.push_back(dot(p - c0, u));
    vs.push_back(dot(p - c0, v));
  }
  std::sort(us.begin(), us.end());
  std::sort(vs.begin(), vs.end());
  const double w0 = (us[2] + us[3] - us[0] - us[1]) / 2;
  const double h0 = (vs[2] + vs[3] - vs[0] - vs[1]) / 2;
  const PointD centre0 =
      c0 + ((us[0] + us[1] + us[2] + us[3]) / 4) * u + ((vs[0] + vs[1] + vs[2] + vs[3]) / 4) * v;
  return {centre0, w0, h0, theta0};
}

// Rectangle: centre, width, height, angle (scaled by the size so one step fits all).
Fit fit_rectangle(const PreparedStroke& s, const RectangleStart& start) {
  const double size = s.size;
  const ShapeBuilder rect = [size](const std::vector<double>& p) -> std::optional<CleanShape> {
    if (p[2] <= 0 || p[3] <= 0) return std::nullopt;
    CleanShape c;
    c.path = closed_ring(rectangle_corners({p[0], p[1]}, p[2], p[3], p[4] / size));
    return c;
  };
  const Refinement r =
      refine_minimax(s, {start.centre.x, start.centre.y, start.w, start.h, start.theta * size},
                     rect, 0.02 * size, true);
  double theta = r.params[4] / size, w = r.params[2], h = r.params[3];
  normalise(theta, w, h);
  const PointD rc{r.params[0], r.params[1]};
  Fit rf =
      make_fit(ShapeClass::kRectangle, rectangle_corners(rc, w, h, theta), r.objective, rc, theta);
  rf.params.radius_x = w / 2;
  rf.params.radius_y = h / 2;
  return rf;
}

// Square: centre, side, angle, from the fitted rectangle.
Fit fit_square(const PreparedStroke& s, const Fit& rectangle) {
  const double size = s.size;
  const ShapeBuilder square = [size](const std::vector<double>& p) -> std::optional<CleanShape> {
    if (p[2] <= 0) return std::nullopt;
    CleanShape c;
    c.path = closed_ring(rectangle_corners({p[0], p[1]}, p[2], p[2], p[3] / size));
    return c;
  };
  const PointD rc = rectangle.params.center;
  const double w = 2 * rectangle.params.radius_x, h = 2 * rectangle.params.radius_y;
  const Refinement sq = refine_minimax(
      s, {rc.x, rc.y, (w + h) / 2, rectangle.params.rotation * size}, square, 0.02 * size, true);
  double st = sq.params[3] / size, side = sq.params[2], side2 = side;
  normalise(st, side, side2);
  const PointD sc{sq.params[0], sq.params[1]};
  Fit sf =
      make_fit(ShapeClass::kSquare, rectangle_corners(sc, side, side, st), sq.objective, sc, st);
  sf.params.radius_x = sf.params.radius_y = side / 2;
  return sf;
}

// The rhombus with centre c, one diagonal along direction theta and half-diagonals a (along
// theta) and b (across): its corners in turn.
std::vector<PointD> rhombus_corners(PointD c, double a, double b, double theta) {
  const PointD u{std::cos(theta), std::sin(theta)};
  const PointD v{-u.y, u.x};
  return {c + a * u, c + b * v, c - a * u, c - b * v};
}

// Diamond: a rhombus in any orientation (centre, two half-diagonals, angle), seeded with the
// quadrilateral's diagonals: the one through its corners 0 and 2 gives the angle, the corners'
// reach along and across it the half-diagonals.
Fit fit_diamond(const PreparedStroke& s, const std::vector<PointD>& q, PointD c0) {
  const double size = s.size;
  const double theta0 = std::atan2(q[2].y - q[0].y, q[2].x - q[0].x);
  const PointD u{std::cos(theta0), std::sin(theta0)};
  const PointD v{-u.y, u.x};
  const double a0 = (std::abs(dot(q[0] - c0, u)) + std::abs(dot(q[2] - c0, u))) / 2;
  const double b0 = (std::abs(dot(q[1] - c0, v)) + std::abs(dot(q[3] - c0, v))) / 2;
  const ShapeBuilder rhombus = [size](const std::vector<double>& p) -> std::optional<CleanShape> {
    if (p[2] <= 0 || p[3] <= 0) return std::nullopt;
    CleanShape c;
    c.path = closed_ring(rhombus_corners({p[0], p[1]}, p[2], p[3], p[4] / size));
    return c;
  };
  const Refinement d =
      refine_minimax(s, {c0.x, c0.y, a0, b0, theta0 * size}, rhombus, 0.02 * size, true);
  double theta = d.params[4] / size, a = d.params[2], b = d.params[3];
  normalise(theta, a, b);
  const PointD dc{d.params[0], d.params[1]};
  Fit df = make_fit(ShapeClass::kDiamond, rhombus_corners(dc, a, b, theta), d.objective, dc, theta);
  df.params.radius_x = a;
  df.params.radius_y = b;
  return df;
}

} // namespace

std::vector<Fit> fit_rectangles(const PreparedStroke& s, const Fit& quad) {
  const std::vector<PointD>& q = quad.params.vertices;
  if (q.size() != 4) return {};
  const Fit rectangle = fit_rectangle(s, rectangle_start(q, quad.params.center));
  return {rectangle, fit_square(s, rectangle), fit_diamond(s, q, quad.params.center)};
}

std::optional<Fit> fit_regular_polygon(const PreparedStroke& s, std::size_t sides, PointD center,
                                       double radius) {
  if (sides < 5 || radius <= 0) return std::nullopt;
  const double size = s.size;
  const double n = static_cast<double>(sides);
  auto corners = [sides, n](PointD c, double r, double theta) {
    std::vector<PointD> v;
    for (std::size_t k = 0; k < sides; ++k) {
      const double a = theta + 2 * std::numbers::pi * static_cast<double>(k) / n;
      v.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
    }
    return v;
  };
  const ShapeBuilder build = [&](const std::vector<double>& p) -> std::optional<CleanShape> {
    if (p[2] <= 0) return std::nullopt;
    CleanShape c;
    c.path = closed_ring(corners({p[0], p[1]}, p[2], p[3] / size));
    return c;
  };
  // Seed the angle from a coarse scan of one period.
  double best_theta = 0, best = INFINITY;
  for (int k = 0; k < 12; ++k) {
    const double theta = 2 * std::numbers::pi / n * k / 12.0;
    const double value = fit_objective(s, *build({center.x, center.y, radius, theta * size}), true);
    if (value < best) {
      best = value;
      best_theta = theta;
    }
  }
  const Refinement r =
      refine_minimax(s, {center.x, center.y, radius, best_theta * size}, build, 0.02 * size, true);
  Fit f;
  f.shape = ShapeClass::kRegularPolygon;
  f.clean = *build(r.params);
  f.fit_error = r.objective;
  f.params.center = {r.params[0], r.params[1]};
  f.params.radius_x = f.params.radius_y = r.params[2];
  f.params.rotation = std::remainder(r.params[3] / size, 2 * std::numbers::pi / n);
  f.params.vertices = corners(f.params.center, r.params[2], r.params[3] / size);
  return f;
}

} // namespace penshape::recognize_detail
