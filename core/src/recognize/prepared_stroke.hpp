#pragma once
// A validated stroke ready for fitting: duplicates removed, its size, and an arc-length
// resampling that every fitter works on (so a long stroke costs no more to fit than a short one).
#include <vector>

#include "geometry.hpp"
#include "penshape/core/recognize.hpp"

namespace penshape::recognize_detail {

inline constexpr std::size_t kFitPoints = 48; // resampled points the fitters use

struct PreparedStroke {
  std::vector<PointD> points;     // the pen path: samples without consecutive duplicates
  std::vector<PointD> fit_points; // kFitPoints points evenly spaced along the path, ends kept
  PointD centroid;                // of fit_points
  double length = 0.0;            // path length
  double size = 0.0;              // bounding-box diagonal
  double gap = 0.0;               // distance from the last point to the first
};

// Throws InvalidInput for non-finite or too large coordinates, too many samples, fewer than two
// distinct positions.
void validate_samples(const std::vector<StrokePoint>& samples, const RecognizerConfig& config);

// Assumes validate_samples passed.
PreparedStroke prepare(const std::vector<StrokePoint>& samples);
PreparedStroke prepare_points(std::vector<PointD> points); // points already deduplicated

} // namespace penshape::recognize_detail
