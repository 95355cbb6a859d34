#pragma once
// The circular arc from a to b whose midpoint lies `bulge` to the left of the chord a -> b: an
// arrow's curved shaft. Written once for the recognizer (which certifies chords of it) and snap
// (which draws it). Doubles: for proposals and drawing, never for a certified decision.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "penshape/core/point_arithmetic.hpp"

namespace penshape {

struct BulgeArc {
  PointD centre;
  double radius = 0.0;
  double start = 0.0; // the angle of a, seen from the centre
  double sweep = 0.0; // signed: negative (clockwise in x, y) for a left bulge
  PointD at(double t) const {
    return {centre.x + radius * std::cos(t), centre.y + radius * std::sin(t)};
  }
};

// Requires a != b and bulge != 0.
inline BulgeArc bulge_arc(PointD a, PointD b, double bulge) {
  const double c = distance(a, b);
  const PointD u = (1.0 / c) * (b - a);
  const PointD n{-u.y, u.x};
  const PointD mid = 0.5 * (a + b) + bulge * n;
  BulgeArc arc;
  arc.radius = (c * c / 4.0 + bulge * bulge) / (2.0 * std::abs(bulge));
  // The centre is on the chord's normal, on the side away from the bulge.
  arc.centre = mid - (bulge > 0 ? arc.radius : -arc.radius) * n;
  arc.start = std::atan2(a.y - arc.centre.y, a.x - arc.centre.x);
  // Past a half circle when the bulge exceeds the radius.
  const double minor = 2.0 * std::asin(std::min(1.0, c / (2.0 * arc.radius)));
  const double magnitude = std::abs(bulge) <= arc.radius ? minor : 2.0 * std::numbers::pi - minor;
  arc.sweep = bulge > 0 ? -magnitude : magnitude;
  return arc;
}

} // namespace penshape
