// Round families: circle and circular arc (algebraic Kasa fit, then minimax refinement, the
// circular-annulus width), and the ellipse (principal axes of the resampled outline, a conic
// least-squares fit in that frame, then minimax refinement).
#include <array>
#include <cmath>
#include <numbers>

#include "recognize/fitting/fit.hpp"

namespace penshape::recognize_detail {
namespace {

// Solves the n x n system m x = b by Gaussian elimination with partial pivoting.
template <std::size_t N>
bool solve(std::array<std::array<double, N>, N> m, std::array<double, N> b,
           std::array<double, N>& x) {
  for (std::size_t c = 0; c < N; ++c) {
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < N; ++r) {
      if (std::abs(m[r][c]) > std::abs(m[piv][c])) piv = r;
    }
    if (std::abs(m[piv][c]) < 1e-300) return false;
    std::swap(m[c], m[piv]);
    std::swap(b[c], b[piv]);
    for (std::size_t r = c + 1; r < N; ++r) {
      const double f = m[r][c] / m[c][c];
      for (std::size_t k = c; k < N; ++k) m[r][k] -= f * m[c][k];
      b[r] -= f * b[c];
    }
  }
  for (std::size_t c = N; c-- > 0;) {
    double v = b[c];
    for (std::size_t k = c + 1; k < N; ++k) v -= m[c][k] * x[k];
    x[c] = v / m[c][c];
  }
  return std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
}

// Kasa: least squares of x^2 + y^2 + D x + E y + F over the points (centred at c).
bool kasa(const std::vector<PointD>& pts, PointD c, PointD& center, double& radius) {
  std::array<std::array<double, 3>, 3> m{};
  std::array<double, 3> b{};
  for (const PointD& p0 : pts) {
    const PointD p = p0 - c;
    const std::array<double, 3> row{p.x, p.y, 1.0};
    const double rhs = -(p.x * p.x + p.y * p.y);
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t j = 0; j < 3; ++j) m[i][j] += row[i] * row[j];
      b[i] += row[i] * rhs;
    }
  }
  std::array<double, 3> x{};
  if (!solve(m, b, x)) return false;
  const PointD cc{-x[0] / 2, -x[1] / 2};
  const double r2 = cc.x * cc.x + cc.y * cc.y - x[2];
  if (!(r2 > 0)) return false;
  center = c + cc;
  radius = std::sqrt(r2);
  return true;
}

// The arc a circle makes along the stroke: start angle and signed sweep of the fit points.
void arc_range(const std::vector<PointD>& pts, PointD c, double& t0, double& sweep) {
  t0 = std::atan2(pts.front().y - c.y, pts.front().x - c.x);
  double prev = t0;
  sweep = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const double a = std::atan2(pts[i].y - c.y, pts[i].x - c.x);
    sweep += std::remainder(a - prev, 2 * std::numbers::pi);
    prev = a;
  }
}

// The circle of refinement parameters {centre x, centre y, radius}; none for a radius <= 0.
std::optional<CleanShape> circle_of(const std::vector<double>& p) {
  if (p[2] <= 0) return std::nullopt;
  CleanShape shape;
  shape.kind = CleanShape::Kind::kCircle;
  shape.center = {p[0], p[1]};
  shape.rx = shape.ry = p[2];
  return shape;
}

// A circle's or an arc's fit at its refined parameters.
Fit round_fit(ShapeClass shape, const ShapeBuilder& build, const Refinement& ref) {
  Fit f;
  f.shape = shape;
  f.clean = *build(ref.params);
  f.fit_error = ref.objective;
  f.params.center = f.clean.center;
  f.params.radius_x = f.params.radius_y = f.clean.rx;
  return f;
}

} // namespace

std::optional<Fit> fit_circle(const PreparedStroke& s) {
  PointD c;
  double r = 0;
  if (!kasa(s.fit_points, s.centroid, c, r) || r > 10 * s.size) return std::nullopt;
  const ShapeBuilder build = circle_of;
  const Refinement ref = refine_minimax(s, {c.x, c.y, r}, build, 0.02 * s.size, false);
  Fit f = round_fit(ShapeClass::kCircle, build, ref);
  f.params.sweep_angle = 2 * std::numbers::pi;
  return f;
}

std::optional<Fit> fit_arc(const PreparedStroke& s) {
  PointD c;
  double r = 0;
  if (!kasa(s.fit_points, s.centroid, c, r) || r > 10 * s.size) return std::nullopt;
  const ShapeBuilder build = [&s](const std::vector<double>& p) -> std::optional<CleanShape> {
    std::optional<CleanShape> shape = circle_of(p);
    if (!shape) return std::nullopt;
    arc_range(s.fit_points, shape->center, shape->t0, shape->sweep);
    // More than a full turn is not an arc.
    if (std::abs(shape->sweep) >= 2 * std::numbers::pi) return std::nullopt;
    return shape;
  };
  if (!build({c.x, c.y, r})) return std::nullopt;
  const Refinement ref = refine_minimax(s, {c.x, c.y, r}, build, 0.02 * s.size, true);
  Fit f = round_fit(ShapeClass::kArc, build, ref);
  f.params.start_angle = f.clean.t0;
  f.params.sweep_angle = f.clean.sweep;
  f.params.vertices = {f.clean.at(f.clean.t0), f.clean.at(f.clean.t0 + f.clean.sweep)};
  return f;
}

std::optional<Fit> fit_ellipse(const PreparedStroke& s) {
  // Principal axes of the outline.
  const PointD c0 = s.centroid;
  double sxx = 0, syy = 0, sxy = 0;
  for (const PointD& p0 : s.fit_points) {
    const PointD p = p0 - c0;
    sxx += p.x * p.x;
    syy += p.y * p.y;
    sxy += p.x * p.y;
  }
  const double theta0 = 0.5 * std::atan2(2 * sxy, sxx - syy);
  const PointD u{std::cos(theta0), std::sin(theta0)};
  const PointD v{-u.y, u.x};
  // A x^2 + B y^2 + C x + D y = 1 in that frame, scaled by the size for conditioning.
  const double k = 1.0 / s.size;
  std::array<std::array<double, 4>, 4> m{};
  std::array<double, 4> b{};
  for (const PointD& p0 : s.fit_points) {
    const double x = dot(p0 - c0, u) * k;
    const double y = dot(p0 - c0, v) * k;
    const std::array<double, 4> row{x * x, y * y, x, y};
    for (std::size_t i = 0; i < 4; ++i) {
      for (std::size_t j = 0; j < 4; ++j) m[i][j] += row[i] * row[j];
      b[i] += row[i];
    }
  }
  std::array<double, 4> q{};
  if (!solve(m, b, q) || !(q[0] > 0) || !(q[1] > 0)) return std::nullopt;
  const double x0 = -q[2] / (2 * q[0]);
  const double y0 = -q[3] / (2 * q[1]);
  const double g = 1 + q[2] * q[2] / (4 * q[0]) + q[3] * q[3] / (4 * q[1]);
  if (!(g > 0)) return std::nullopt;
  const double a0 = std::sqrt(g / q[0]) / k;
  const double b0 = std::sqrt(g / q[1]) / k;
  const PointD centre0 = c0 + (x0 / k) * u + (y0 / k) * v;
  const double size = s.size;
  if (a0 > 10 * size || b0 > 10 * size) return std::nullopt;

  const ShapeBuilder build = [size](const std::vector<double>& p) -> std::optional<CleanShape> {
    if (p[2] <= 0 || p[3] <= 0) return std::nullopt;
    CleanShape shape;
    shape.kind = CleanShape::Kind::kEllipse;
    shape.center = {p[0], p[1]};
    shape.rx = p[2];
    shape.ry = p[3];
    shape.rotation = p[4] / size;
    return shape;
  };
  const Refinement ref =
      refine_minimax(s, {centre0.x, centre0.y, a0, b0, theta0 * size}, build, 0.02 * size, false);
  Fit f;
  f.shape = ShapeClass::kEllipse;
  f.clean = *build(ref.params);
  // Report the major axis first, the rotation in (-pi/2, pi/2].
  double rot = f.clean.rotation, a = f.clean.rx, bb = f.clean.ry;
  if (bb > a) {
    std::swap(a, bb);
    rot += std::numbers::pi / 2;
  }
  rot = std::remainder(rot, std::numbers::pi);
  f.clean.rx = a;
  f.clean.ry = bb;
  f.clean.rotation = rot;
  f.fit_error = ref.objective;
  f.params.center = f.clean.center;
  f.params.radius_x = a;
  f.params.radius_y = bb;
  f.params.rotation = rot;
  f.params.sweep_angle = 2 * std::numbers::pi;
  return f;
}

} // namespace penshape::recognize_detail
