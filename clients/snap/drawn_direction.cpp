// Reversing open clean shapes to the drawn direction (see drawn_direction.hpp).
#include "drawn_direction.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace penshape::snap {
namespace {

double dist(PointD a, PointD b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Whether a shape from `first` to `last` fits the ink better reversed.
bool backwards(PointD first, PointD last, PointD start, PointD end) {
  return dist(start, last) + dist(end, first) < dist(start, first) + dist(end, last);
}

PointD arc_point(const ShapeParams& p, double angle) {
  return {p.center.x + p.radius_x * std::cos(angle), p.center.y + p.radius_x * std::sin(angle)};
}

// A double arrow's tail and tip swap, with their barbs, bends and clean path.
void reverse_double_arrow(Recognition& r) {
  ShapeParams& p = r.params;
  std::swap(p.vertices[0], p.vertices[1]);
  std::swap(p.vertices[2], p.vertices[4]);
  std::swap(p.vertices[3], p.vertices[5]);
  std::reverse(p.shaft_bends.begin(), p.shaft_bends.end());
  p.shaft_bulge = -p.shaft_bulge; // left of tail -> tip is right of tip -> tail
  std::reverse(r.clean.begin(), r.clean.end());
}

} // namespace

bool orient_like_drawn(Recognition& r, PointD start, PointD end) {
  ShapeParams& p = r.params;
  switch (r.shape) {
    case ShapeClass::kSegment:
    case ShapeClass::kPolyline:
      if (p.vertices.size() >= 2 && backwards(p.vertices.front(), p.vertices.back(), start, end)) {
        std::reverse(p.vertices.begin(), p.vertices.end());
        std::reverse(r.clean.begin(), r.clean.end());
      }
      return false;
    case ShapeClass::kArc:
      if (backwards(arc_point(p, p.start_angle), arc_point(p, p.start_angle + p.sweep_angle), start,
                    end)) {
        p.start_angle += p.sweep_angle;
        p.sweep_angle = -p.sweep_angle;
        std::reverse(r.clean.begin(), r.clean.end());
      }
      return false;
    case ShapeClass::kDoubleArrow:
      if (p.vertices.size() == 6 && backwards(p.vertices[0], p.vertices[1], start, end)) {
        reverse_double_arrow(r);
      }
      return false;
    case ShapeClass::kArrow: // the head stays where it was drawn; the writing order follows the pen
      return p.vertices.size() == 4 && backwards(p.vertices[0], p.vertices[1], start, end);
    default:
      return false;
  }
}

} // namespace penshape::snap
