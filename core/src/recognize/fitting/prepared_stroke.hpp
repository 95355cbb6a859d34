#pragma once
// A validated stroke ready for fitting: duplicates removed, thinned within a certified tolerance
// (recognize.hpp, "Dense strokes"), its size, and an arc-length resampling that every fitter
// works on (so a long or dense stroke costs no more to fit than a short one).
#include <optional>
#include <vector>

#include "penshape/core/recognize.hpp"
#include "recognize/fitting/geometry.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {

struct PreparedStroke {
  // The pen path A' the certificate and the fitters see: the samples without consecutive
  // duplicates, thinned so that H(A, A') <= thinning (A = every distinct sample).
  std::vector<PointD> points;
  double thinning = 0.0;          // tau: the certificate adds it to its bound (0: not thinned)
  std::vector<PointD> fit_points; // kFitPoints points evenly spaced along A, ends kept
  PointD centroid;                // of fit_points
  double length = 0.0;            // length of A
  double size = 0.0;              // bounding-box diagonal of A
  double gap = 0.0;               // distance from the last point to the first
  // How many strokes were joined into `points` (a group's chain, stroke_chain.hpp): at a join the
  // path steps across a pen-up jump, a turn the hand did not make.
  std::size_t pieces = 1;
  // A group's strokes each as drawn (their own directions, which the chain may reverse),
  // resampled as fit_points are: how each stroke traces a shape (empty for one stroke).
  std::vector<std::vector<PointD>> piece_fit_points;
  // The turns along `points`, sharpest first (turn_corners.cpp, which reads several corner counts
  // of one stroke from them), made on first use: most strokes never need them.
  struct PathTurn {
    double at = 0.0;   // arc length along `points`
    double turn = 0.0; // radians
  };
  mutable std::optional<std::vector<PathTurn>> turns_by_sharpness;
  // The closed corner chains of fit_points, index k for k corners (corners.cpp, which finds every
  // count in one search), made on first use.
  mutable std::vector<std::vector<std::size_t>> closed_corner_chains;
};

// Throws InvalidInput for no samples, non-finite or too large coordinates, too many samples. One
// distinct position is valid: a dot (dot.hpp), which the callers answer before preparing.
void validate_samples(const std::vector<StrokePoint>& samples, const RecognizerConfig& config);

// The stroke's ink polygon when one is given (StrokeInput::ink, else the one ink_when_needed
// returns: obtained here, so call it only once Q is needed), else null. Throws InvalidInput for an
// empty one, and whatever ink_when_needed throws.
const InkPolygon* given_ink(const StrokeInput& stroke);

// The thinning tolerance tau for a stroke checked against epsilon (RecognizerConfig::
// thin_tolerance_fraction * epsilon; 0 turns thinning off).
double thinning_tolerance(const RecognizerConfig& config, double epsilon);

// Assumes validate_samples passed and the samples are not a dot. `tau` as thinning_tolerance()
// gives it.
PreparedStroke prepare(const std::vector<StrokePoint>& samples, double tau);
PreparedStroke prepare_points(std::vector<PointD> points, double tau); // already deduplicated

} // namespace penshape::recognize_detail
