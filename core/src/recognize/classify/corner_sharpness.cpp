// Turns of a closed stroke at a polygon's corners (corner_sharpness.hpp).
#include "recognize/classify/corner_sharpness.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "recognize/fitting/path_turn.hpp"

namespace penshape::recognize_detail {

double least_corner_share(const std::vector<PointD>& stroke, const std::vector<PointD>& corners,
                          double window) {
  return measured_corner_share(stroke, corners, window).value_or(0.0);
}

std::optional<double> measured_corner_share(const std::vector<PointD>& stroke,
                                            const std::vector<PointD>& corners, double window) {
  const ArcLengthPath path(stroke);
  const std::size_t n = corners.size();
  double least = INFINITY;
  for (std::size_t k = 0; k < n; ++k) {
    const PointD before = corners[(k + n - 1) % n], v = corners[k], after = corners[(k + 1) % n];
    const double theta = angle_between(v - before, after - v);
    if (theta <= 0.0) continue;
    const double half_width = window * std::min(distance(before, v), distance(v, after));
    const std::optional<double> turn = path.turn_at(path.nearest(v).at, half_width);
    if (turn) least = std::min(least, *turn / theta);
  }
  if (!std::isfinite(least)) return std::nullopt;
  return least;
}

} // namespace penshape::recognize_detail
