// Validation and preparation of stroke samples.
#include "recognize/fitting/prepared_stroke.hpp"

#include <cmath>
#include <string>

#include "recognize/fitting/thin_path.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {

namespace {}

std::vector<PointD> resample(std::span<const PointD> path, std::size_t count) {
  std::vector<PointD> out;
  if (path.empty() || count == 0) return out;
  const double total = path_length(path);
  if (count == 1 || total <= 0.0) return std::vector<PointD>(count, path.front());
  const double step = total / static_cast<double>(count - 1);
  out.reserve(count);
  out.push_back(path.front());
  std::size_t seg = 0;
  double seg_start = 0.0; // arc length at path[seg]
  for (std::size_t k = 1; k + 1 < count; ++k) {
    const double target = step * static_cast<double>(k);
    while (seg + 1 < path.size() - 1 && seg_start + distance(path[seg], path[seg + 1]) < target) {
      seg_start += distance(path[seg], path[seg + 1]);
      ++seg;
    }
    const double len = distance(path[seg], path[seg + 1]);
    const double f = len > 0.0 ? std::clamp((target - seg_start) / len, 0.0, 1.0) : 0.0;
    out.push_back(path[seg] + f * (path[seg + 1] - path[seg]));
  }
  out.push_back(path.back());
  return out;
}

const InkPolygon* given_ink(const StrokeInput& stroke) {
  const InkPolygon* ink = stroke.ink;
  if (ink == nullptr && stroke.ink_when_needed) {
    ink = stroke.ink_when_needed();
    if (ink == nullptr)
      throw InvalidInput("recognize: the ink polygon was announced but not given");
  }
  if (ink != nullptr && ink->region.empty()) {
    throw InvalidInput("recognize: the ink polygon is empty");
  }
  return ink;
}

void validate_samples(const std::vector<StrokePoint>& samples, const RecognizerConfig& config) {
  auto finite_non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!finite_non_negative(config.pen_radius) || !finite_non_negative(config.tolerance)) {
    throw InvalidInput("recognize: pen radius and tolerance must be finite and >= 0 (0 = default)");
  }
  if (!positive(config.default_pen_radius_fraction) || !positive(config.tolerance_size_fraction) ||
      !finite_non_negative(config.tolerance_pen_radii) ||
      !positive(config.max_tolerance_fraction) || !positive(config.straight_fraction) ||
      !std::isfinite(config.arc_monotone_turning)) {
    throw InvalidInput("recognize: the configuration's fractions must be finite and positive");
  }
  if (!(config.thin_tolerance_fraction >= 0.0 && config.thin_tolerance_fraction <= 0.25)) {
    throw InvalidInput("recognize: thin_tolerance_fraction must be within [0, 0.25]");
  }
  if (samples.empty()) throw InvalidInput("recognize: the stroke has no samples");
  if (samples.size() > config.max_samples) {
    throw InvalidInput("recognize: the stroke has " + std::to_string(samples.size()) +
                       " samples, more than the limit of " + std::to_string(config.max_samples));
  }
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const StrokePoint& s = samples[i];
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.t)) {
      throw InvalidInput("recognize: sample " + std::to_string(i) + " is not finite");
    }
    if (std::abs(s.x) > kMaxAbsCoordinate || std::abs(s.y) > kMaxAbsCoordinate) {
      throw InvalidInput("recognize: sample " + std::to_string(i) +
                         " has a coordinate beyond the limit |x|, |y| <= 1e9");
    }
  }
}

double thinning_tolerance(const RecognizerConfig& config, double epsilon) {
  return config.thin_tolerance_fraction * epsilon;
}

PreparedStroke prepare_points(std::vector<PointD> points, double tau) {
  PreparedStroke p;
  PointD lo = points.front();
  PointD hi = lo;
  for (const PointD& q : points) {
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
  }
  // Size, length, gap and the fit points come from every sample (linear, and as without
  // thinning); the certificate and the fitters' point scans use the thinned path.
  p.size = distance(lo, hi);
  p.length = path_length(points);
  p.gap = distance(points.front(), points.back());
  p.fit_points = resample(points, kFitPoints);
  if (tau > 0.0) {
    p.points = thin_path(points, tau);
    p.thinning = tau;
  } else {
    p.points = std::move(points);
  }
  PointD sum;
  for (const PointD& q : p.fit_points) sum = sum + q;
  p.centroid = (1.0 / static_cast<double>(p.fit_points.size())) * sum;
  return p;
}

PreparedStroke prepare(const std::vector<StrokePoint>& samples, double tau) {
  std::vector<PointD> points;
  points.reserve(samples.size());
  for (const StrokePoint& s : samples) {
    const PointD q{s.x, s.y};
    if (points.empty() || !(points.back() == q)) points.push_back(q);
  }
  return prepare_points(std::move(points), tau);
}

} // namespace penshape::recognize_detail
