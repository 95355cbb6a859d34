// Turns of a closed stroke at a polygon's corners (corner_sharpness.hpp).
#include "recognize/classify/corner_sharpness.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "recognize/fitting/path_turn.hpp"

namespace penshape::recognize_detail {

double least_corner_share(const std::vector<PointD>& stroke, const std::vector<PointD>& corners,
                          double window) {
  return measured_corner_share(stroke, corners, window).value_or(0.0);
}

std::optional<double> stroke_turn_at_corner(const ArcLengthPath& stroke,
                                            const std::vector<PointD>& corners, std::size_t k,
                                            double window) {
  const std::size_t n = corners.size();
  const PointD before = corners[(k + n - 1) % n], v = corners[k], after = corners[(k + 1) % n];
  const double half_width = window * std::min(distance(before, v), distance(v, after));
  return stroke.turn_at(stroke.nearest(v).at, half_width);
}

std::vector<double> corner_shares(const std::vector<PointD>& stroke,
                                  const std::vector<PointD>& corners, double window) {
  const ArcLengthPath path(stroke);
  const std::size_t n = corners.size();
  std::vector<double> shares;
  for (std::size_t k = 0; k < n; ++k) {
    const PointD before = corners[(k + n - 1) % n], v = corners[k], after = corners[(k + 1) % n];
    const double theta = angle_between(v - before, after - v);
    if (theta <= 0.0) continue;
    const std::optional<double> turn = stroke_turn_at_corner(path, corners, k, window);
    if (turn) shares.push_back(*turn / theta);
  }
  return shares;
}

std::optional<double> mean_corner_share(const std::vector<PointD>& stroke,
                                        const std::vector<PointD>& corners, double window) {
  const std::vector<double> shares = corner_shares(stroke, corners, window);
  if (shares.empty()) return std::nullopt;
  return std::accumulate(shares.begin(), shares.end(), 0.0) / static_cast<double>(shares.size());
}

std::optional<double> measured_corner_share(const std::vector<PointD>& stroke,
                                            const std::vector<PointD>& corners, double window) {
  const std::vector<double> shares = corner_shares(stroke, corners, window);
  if (shares.empty()) return std::nullopt;
  return *std::min_element(shares.begin(), shares.end());
}

} // namespace penshape::recognize_detail
