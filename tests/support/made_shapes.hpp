#pragma once
// Shapes made from real strokes where no shared corpus holds them: a real one-stroke rectangle
// (its wobble, corners and closure are the writer's own) mapped onto a diamond or a square on
// its corner; only the affine frame is chosen. A real one-stroke circle made a polygon of n
// corners: its wobble, closure and squash are the writer's own, only the corners are added.
// Shared by the recognition tests and benches.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::cases {

inline constexpr double kDiamondAcross = 0.6; // half-diagonal ratio of the made diamonds (62 deg)

// The stroke's box to the unit square (x 100), turned 45 degrees, stretched by `across` along y:
// a real one-stroke rectangle made a diamond (across < 1) or a square on its corner (across = 1).
inline std::vector<StrokePoint> on_corner(const std::vector<StrokePoint>& in, double across) {
  double xlo = in[0].x, xhi = xlo, ylo = in[0].y, yhi = ylo;
  for (const StrokePoint& p : in) {
    xlo = std::min(xlo, p.x), xhi = std::max(xhi, p.x);
    ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
  }
  const double w = std::max(xhi - xlo, 1e-9), h = std::max(yhi - ylo, 1e-9);
  const double c = std::cos(std::numbers::pi / 4), s = std::sin(std::numbers::pi / 4);
  std::vector<StrokePoint> out = in;
  for (StrokePoint& p : out) {
    const double x = 100.0 * (p.x - xlo) / w, y = 100.0 * (p.y - ylo) / h;
    p = {c * x - s * y, across * (s * x + c * y), p.t};
  }
  return out;
}

// The stroke with points at most `step` apart along it (straight between the samples), so that a
// map that bends it has points where it bends (a hand slows and samples densely at a corner).
inline std::vector<StrokePoint> densified(const std::vector<StrokePoint>& in, double step) {
  std::vector<StrokePoint> out{in.front()};
  for (std::size_t i = 1; i < in.size(); ++i) {
    const StrokePoint a = in[i - 1], b = in[i];
    const int m = std::max(1, static_cast<int>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / step)));
    for (int j = 1; j <= m; ++j) {
      const double t = static_cast<double>(j) / m;
      out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.t + t * (b.t - a.t)});
    }
  }
  return out;
}

// The stroke with points at most 1/400 of its length apart.
inline std::vector<StrokePoint> finely_densified(const std::vector<StrokePoint>& in) {
  double length = 0;
  for (std::size_t i = 1; i < in.size(); ++i) {
    length += std::hypot(in[i].x - in[i - 1].x, in[i].y - in[i - 1].y);
  }
  return densified(in, std::max(length / 400.0, 1e-9));
}

// A real one-stroke circle made a polygon of n corners: each point's distance from the stroke's
// centroid is multiplied by the regular n-gon's (circumradius 1) in the point's direction, so the
// writer's own deviations from a circle become deviations from the polygon. `turn`: the polygon's
// first corner direction (radians).
inline std::vector<StrokePoint> made_polygon(const std::vector<StrokePoint>& in, int n,
                                             double turn) {
  double cx = 0, cy = 0;
  std::vector<StrokePoint> out = finely_densified(in);
  for (const StrokePoint& p : out) cx += p.x, cy += p.y;
  cx /= static_cast<double>(out.size()), cy /= static_cast<double>(out.size());
  const double sector = 2.0 * std::numbers::pi / n;
  for (StrokePoint& p : out) {
    const double dx = p.x - cx, dy = p.y - cy;
    const double a = std::remainder(std::atan2(dy, dx) - turn - 0.5 * sector, sector);
    const double k = std::cos(0.5 * sector) / std::cos(a);
    p.x = cx + k * dx, p.y = cy + k * dy;
  }
  return out;
}

// The index of an arrow stroke's tip: its sample farthest from its start.
inline std::size_t arrow_tip(const std::vector<StrokePoint>& in) {
  std::size_t tip = 0;
  double far = -1.0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const double d = std::hypot(in[i].x - in[0].x, in[i].y - in[0].y);
    if (d > far) far = d, tip = i;
  }
  return tip;
}

// How a made arrow's shaft turns: by `turn` radians (positive: to the left), spread over the
// share `width` of the shaft centred at the share `at` (width 1, at 0.5: evenly, a circular arc;
// a narrow width: an elbow); and its length times `stretch` (a long arrow with the head as drawn).
struct ShaftTurn {
  double turn = 0.0;
  double at = 0.5;
  double width = 1.0;
  double stretch = 1.0;
};

// A real one-stroke arrow (tail first, the tip its sample farthest from the start) made a curved,
// bent or longer one: each shaft sample (up to where the stroke first comes within 5% of the shaft
// of the tip) keeps its distance along (times bend.stretch) and across the shaft about a centre
// line whose heading turns as `bend` says; the head (every later sample: a barb drawn out and back
// before the farthest sample is the head's too) moves rigidly with the tip and the shaft's end
// direction. The writer's wobble, head and speed are their own. `tip_at`, when given, is set to the
// made arrow's tip (its index in the result).
inline std::vector<StrokePoint> bent_arrow(const std::vector<StrokePoint>& stroke, ShaftTurn bend,
                                           std::size_t* tip_at = nullptr) {
  std::vector<StrokePoint> in = finely_densified(stroke);
  const std::size_t tip = arrow_tip(in);
  if (tip_at != nullptr) *tip_at = tip;
  const double ox = in[0].x, oy = in[0].y;
  const double shaft = std::hypot(in[tip].x - ox, in[tip].y - oy);
  if (shaft <= 0) return in;
  const double ux = (in[tip].x - ox) / shaft, uy = (in[tip].y - oy) / shaft;
  std::size_t arrival = tip;
  for (std::size_t i = 0; i < tip; ++i) {
    if (std::hypot(in[i].x - in[tip].x, in[i].y - in[tip].y) <= 0.05 * shaft) {
      arrival = i;
      break;
    }
  }
  const double made_shaft = bend.stretch * shaft;
  auto heading = [&](double s) {
    const double lo = bend.at - 0.5 * bend.width;
    return bend.turn * std::clamp((s / made_shaft - lo) / bend.width, 0.0, 1.0);
  };
  // The centre line at `steps` + 1 evenly spaced distances along the shaft.
  constexpr int steps = 800;
  std::vector<double> cx{0.0}, cy{0.0};
  for (int k = 0; k < steps; ++k) {
    const double h = heading(made_shaft * (k + 0.5) / steps);
    cx.push_back(cx.back() + made_shaft / steps * std::cos(h));
    cy.push_back(cy.back() + made_shaft / steps * std::sin(h));
  }
  auto centre = [&](double s, double& x, double& y) {
    const double f = std::clamp(s / made_shaft, 0.0, 1.0) * steps;
    const auto k = std::min(static_cast<std::size_t>(f), static_cast<std::size_t>(steps - 1));
    const double t = f - static_cast<double>(k);
    x = cx[k] + t * (cx[k + 1] - cx[k]) + std::min(s, 0.0);
    y = cy[k] + t * (cy[k + 1] - cy[k]);
  };
  const double end = heading(made_shaft);
  std::vector<StrokePoint> out = in;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const double dx = in[i].x - ox, dy = in[i].y - oy;
    const double s = dx * ux + dy * uy, across = ux * dy - uy * dx;
    // In the shaft's frame (x along it from the tail, y to its left), then back.
    double x = 0, y = 0;
    if (i <= arrival) {
      centre(bend.stretch * s, x, y);
      const double h = heading(bend.stretch * s);
      x -= across * std::sin(h), y += across * std::cos(h);
    } else {
      centre(made_shaft, x, y);
      x += (s - shaft) * std::cos(end) - across * std::sin(end);
      y += (s - shaft) * std::sin(end) + across * std::cos(end);
    }
    out[i].x = ox + x * ux - y * uy, out[i].y = oy + x * uy + y * ux;
  }
  return out;
}

// Whether an answer is the polygon of n corners a made_polygon(.., n, ..) was made as: a polygon
// or regular polygon with n vertices (a made octagon read as a regular pentagon is wrong).
inline bool is_polygon_of(ShapeClass shape, const ShapeParams& params, int n) {
  return (shape == ShapeClass::kPolygon || shape == ShapeClass::kRegularPolygon) &&
         params.vertices.size() == static_cast<std::size_t>(n);
}
inline bool is_polygon_of(const Recognition& r, int n) {
  return is_polygon_of(r.shape, r.params, n);
}

// The sample indices of a made_polygon(in, n, turn)'s corners, in path order: for each corner
// direction, the sample whose direction from the centroid is nearest it.
inline std::vector<std::size_t> made_polygon_corners(const std::vector<StrokePoint>& made, int n,
                                                     double turn) {
  double cx = 0, cy = 0;
  for (const StrokePoint& p : made) cx += p.x, cy += p.y;
  cx /= static_cast<double>(made.size()), cy /= static_cast<double>(made.size());
  std::vector<std::size_t> out;
  for (int k = 0; k < n; ++k) {
    const double corner = turn + 2.0 * std::numbers::pi * k / n;
    std::size_t best = 0;
    double off = INFINITY;
    for (std::size_t i = 0; i < made.size(); ++i) {
      const double a = std::abs(std::remainder(std::atan2(made[i].y - cy, made[i].x - cx) - corner,
                                               2.0 * std::numbers::pi));
      if (a < off) off = a, best = i;
    }
    out.push_back(best);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Douglas-Peucker: keeps the points of in[a..b] farther than `tolerance` from the chord.
inline void keep_far_points(const std::vector<StrokePoint>& in, std::size_t a, std::size_t b,
                            double tolerance, std::vector<bool>& keep) {
  double farthest = -1.0;
  std::size_t at = a;
  const double dx = in[b].x - in[a].x, dy = in[b].y - in[a].y, chord = std::hypot(dx, dy);
  for (std::size_t i = a + 1; i < b; ++i) {
    const double ex = in[i].x - in[a].x, ey = in[i].y - in[a].y;
    const double d = chord > 0 ? std::abs(dy * ex - dx * ey) / chord : std::hypot(ex, ey);
    if (d > farthest) farthest = d, at = i;
  }
  if (farthest <= tolerance) return;
  keep[at] = true;
  keep_far_points(in, a, at, tolerance, keep);
  keep_far_points(in, at, b, tolerance, keep);
}

// The stroke as public sketch collections store drawings: scaled into a 255-unit box, rounded to
// whole units, simplified by Douglas-Peucker at 2 units (a few points per side, sharp turns
// between them).
inline std::vector<StrokePoint> sketch_simplified(const std::vector<StrokePoint>& in) {
  double xlo = in[0].x, xhi = xlo, ylo = in[0].y, yhi = ylo;
  for (const StrokePoint& p : in) {
    xlo = std::min(xlo, p.x), xhi = std::max(xhi, p.x);
    ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
  }
  const double scale = 255.0 / std::max({xhi - xlo, yhi - ylo, 1e-9});
  std::vector<StrokePoint> grid = in;
  for (StrokePoint& p : grid) {
    p.x = std::round((p.x - xlo) * scale), p.y = std::round((p.y - ylo) * scale);
  }
  std::vector<bool> keep(grid.size(), false);
  keep.front() = keep.back() = true;
  keep_far_points(grid, 0, grid.size() - 1, 2.0, keep);
  std::vector<StrokePoint> out;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (keep[i]) out.push_back(grid[i]);
  }
  return out;
}

} // namespace penshape::cases
