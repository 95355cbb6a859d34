#pragma once
// The axis-aligned bounding box of points, written once for core and its clients (the annulus
// sweeps, the CLI's stroke layout). Doubles: for proposals and drawing, never for a decision.
#include <algorithm>
#include <iterator>

namespace penshape {

// An axis-aligned box, x0 <= x1 and y0 <= y1.
struct BoxD {
  double x0, y0, x1, y1;
};

// The bounding box of non-empty points (PointD, StrokePoint: anything with x and y).
template <typename Points>
BoxD bounding_box(const Points& points) {
  const auto& first = *std::begin(points);
  BoxD b{first.x, first.y, first.x, first.y};
  for (const auto& p : points) {
    b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
  }
  return b;
}

} // namespace penshape
