#pragma once
// What arrow fitting (fit_arrow.cpp) and the arrow plausibility rules (arrow_plausibility.cpp)
// share: the limits of a head (in recognize/thresholds.hpp, with every threshold) and the
// directions of a shaft at its ends.
#include <cmath>
#include <numbers>
#include <vector>

#include "recognize/fitting/clean_shape.hpp"
#include "recognize/fitting/path_turn.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {

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
