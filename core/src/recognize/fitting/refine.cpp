// Minimax refinement by compass search, and the shared refinement objective.
#include <cmath>

#include "recognize/fitting/fit.hpp"

namespace penshape::recognize_detail {

double fit_objective(const PreparedStroke& stroke, const CleanShape& shape, bool use_key_points) {
  double worst = max_distance(stroke.fit_points, shape);
  if (!use_key_points) return worst;
  if (shape.kind == CleanShape::Kind::kPolyline) {
    for (const PointD& v : shape.path) {
      worst = std::max(worst, polyline_distance(v, stroke.points));
    }
  } else if (!shape.full_curve()) {
    worst = std::max(worst, polyline_distance(shape.at(shape.t0), stroke.points));
    worst = std::max(worst, polyline_distance(shape.at(shape.t0 + shape.sweep), stroke.points));
  }
  return worst;
}

Refinement refine_minimax(const PreparedStroke& stroke, std::vector<double> params,
                          const ShapeBuilder& build, double initial_step, bool use_key_points) {
  auto evaluate = [&](const std::vector<double>& p) {
    const std::optional<CleanShape> shape = build(p);
    return shape ? fit_objective(stroke, *shape, use_key_points) : INFINITY;
  };
  Refinement best{params, evaluate(params)};
  double step = initial_step;
  const double min_step = initial_step / 32.0;
  // Evaluation budget: the search is a local polish of a least-squares start, not a solver.
  const std::size_t budget = 16 * params.size();
  std::size_t evaluations = 1;
  while (step >= min_step && evaluations < budget) {
    bool improved = false;
    for (std::size_t i = 0; i < best.params.size(); ++i) {
      for (const double sign : {1.0, -1.0}) {
        std::vector<double> trial = best.params;
        trial[i] += sign * step;
        const double value = evaluate(trial);
        ++evaluations;
        if (value < best.objective) {
          // Keep moving that way while it helps (a cheap pattern move).
          best = {trial, value};
          trial[i] += sign * step;
          const double further = evaluate(trial);
          ++evaluations;
          if (further < best.objective) best = {std::move(trial), further};
          improved = true;
          break;
        }
      }
    }
    if (!improved) step /= 2.0;
  }
  return best;
}

} // namespace penshape::recognize_detail
