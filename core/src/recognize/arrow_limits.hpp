#pragma once
// What arrow fitting (fit_arrow.cpp) and the arrow plausibility rules (arrow_plausibility.cpp)
// share: the limits of a head and the directions of a shaft at its ends.
#include <cmath>
#include <numbers>
#include <vector>

#include "clean_shape.hpp"

namespace penshape::recognize_detail {

inline constexpr double kDegree = std::numbers::pi / 180.0;
inline constexpr double kMinHeadAngle = 10.0 * kDegree;
inline constexpr double kMaxHeadAngle = 80.0 * kDegree;
inline constexpr double kMaxBarbFraction = 0.8; // of the shaft
// An arrow is made of straight pieces: like segments and polylines it must fit more tightly than
// round shapes (recognize.hpp, straight_fraction), a little looser since the head is small.
inline constexpr double kStraightFraction = 0.6;

inline double angle_between(PointD a, PointD b) {
  return std::abs(std::atan2(cross(a, b), dot(a, b)));
}

// The direction back along the shaft from the tip (the tangent of a curved shaft, nearly; a bent
// shaft's last piece).
inline PointD shaft_back(PointD tail, PointD tip, double bulge, const std::vector<PointD>& bends) {
  const std::vector<PointD> shaft = shaft_path(tail, tip, bulge, bends);
  return shaft[shaft.size() - 2] - tip;
}

// The same from the tail (towards the tip).
inline PointD shaft_forward(PointD tail, PointD tip, double bulge,
                            const std::vector<PointD>& bends) {
  const std::vector<PointD> shaft = shaft_path(tail, tip, bulge, bends);
  return shaft[1] - tail;
}

} // namespace penshape::recognize_detail
