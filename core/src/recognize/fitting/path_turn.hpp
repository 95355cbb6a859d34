#pragma once
// How sharply a drawn path turns where a shape has a corner: the turn between the chords that
// leave the path's nearest point a given arc length either way. A corner drawn as a corner turns
// there by nearly the shape's whole turn; a curve passing it turns by the arc it spans. Shared by
// the single-stroke polygon rule (classify/) and the drawn-in-pieces corner rule (group/).
#include <cmath>
#include <optional>
#include <vector>

#include "penshape/core/point_arithmetic.hpp"

namespace penshape::recognize_detail {

// The unsigned angle between two directions (radians, 0..pi).
inline double angle_between(PointD a, PointD b) {
  return std::abs(std::atan2(cross(a, b), dot(a, b)));
}

// A polyline with its cumulative arc lengths.
class ArcLengthPath {
 public:
  explicit ArcLengthPath(const std::vector<PointD>& path);
  [[nodiscard]] double length() const { return lengths_.back(); }
  // The point at arc length `at` (clamped to the ends).
  [[nodiscard]] PointD point_at(double at) const;
  // The arc length of the path's point nearest to v, and that distance.
  struct Nearest {
    double at = 0.0;
    double distance = 0.0;
  };
  [[nodiscard]] Nearest nearest(PointD v) const;
  // The turn at arc length `at` between the chords to `at - half_width` and to `at +
  // half_width`; nothing when either runs off an end.
  [[nodiscard]] std::optional<double> turn_at(double at, double half_width) const;

 private:
  const std::vector<PointD>& path_;
  std::vector<double> lengths_;
};

} // namespace penshape::recognize_detail
