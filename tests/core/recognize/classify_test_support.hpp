#pragma once
// What the classifier's rule tests share: strokes from points, and the class recognize() would
// choose with given rule thresholds (no ink, no skeleton).
#include <vector>

#include "penshape/core/recognize.hpp"
#include "recognize/classify/classifier.hpp"
#include "recognize/fitting/prepared_stroke.hpp"

namespace penshape::recognize_detail::test {

// The points as samples 10 ms apart.
inline std::vector<StrokePoint> samples(const std::vector<PointD>& points) {
  std::vector<StrokePoint> out;
  out.reserve(points.size());
  double t = 0;
  for (const PointD& p : points) out.push_back({p.x, p.y, t += 0.01});
  return out;
}

// The stroke prepared as recognize() prepares it at the default tolerance.
inline PreparedStroke prepared(const std::vector<StrokePoint>& stroke) {
  const RecognizerConfig config;
  const ToleranceChoice tol = choose_tolerance(stroke, config);
  return prepare(stroke, thinning_tolerance(config, tol.epsilon));
}

// The class recognize() would choose with these rule thresholds (no ink, no skeleton).
inline ShapeClass chosen(const std::vector<StrokePoint>& stroke, const RuleThresholds& rules) {
  const RecognizerConfig config;
  const ToleranceChoice tol = choose_tolerance(stroke, config);
  const PreparedStroke s = prepare(stroke, thinning_tolerance(config, tol.epsilon));
  const std::vector<Scored> scored =
      evaluate(s, fit_all(s, config, tol.epsilon), tol.epsilon, tol.pen_radius, config, rules);
  return !scored.empty() && scored.front().snap ? scored.front().fit.shape : ShapeClass::kFreeform;
}

} // namespace penshape::recognize_detail::test
