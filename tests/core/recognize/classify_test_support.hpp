#pragma once
// What the classifier's rule tests share: strokes from points, and the class recognize() would
// choose with given rule thresholds (no ink, no skeleton).
#include <optional>
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

// The fit recognize() would choose with these rule thresholds (no ink, no skeleton), or nothing
// (freeform).
inline std::optional<Fit> chosen_fit(const std::vector<StrokePoint>& stroke,
                                     const RuleThresholds& rules) {
  const RecognizerConfig config;
  const ToleranceChoice tol = choose_tolerance(stroke, config);
  const PreparedStroke s = prepare(stroke, thinning_tolerance(config, tol.epsilon));
  std::vector<Scored> scored =
      evaluate(s, fit_all(s, config, tol.epsilon), tol.epsilon, tol.pen_radius, config, rules);
  if (scored.empty() || !scored.front().snap) return std::nullopt;
  return std::move(scored.front().fit);
}

// The class recognize() would choose with these rule thresholds.
inline ShapeClass chosen(const std::vector<StrokePoint>& stroke, const RuleThresholds& rules) {
  const std::optional<Fit> f = chosen_fit(stroke, rules);
  return f ? f->shape : ShapeClass::kFreeform;
}

} // namespace penshape::recognize_detail::test
