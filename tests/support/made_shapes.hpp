#pragma once
// Shapes made from real strokes where no shared corpus holds them: a real one-stroke rectangle
// (its wobble, corners and closure are the writer's own) mapped onto a diamond or a square on
// its corner; only the affine frame is chosen. Shared by the recognition tests and benches.
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

} // namespace penshape::cases
