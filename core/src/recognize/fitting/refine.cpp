// Minimax refinement by compass search, and the shared refinement objective.
#include <cmath>

#include "recognize/fitting/fit.hpp"

namespace penshape::recognize_detail {

double raise_to_polyline_distance(std::span<const PointD> points, std::span<const PointD> path,
                                  double worst, std::size_t& hint, double stop_at,
                                  std::size_t* raised_at) {
  if (path.size() < 2) { // one point (or none: infinitely far), as polyline_distance answers
    for (const PointD& p : points) worst = std::max(worst, polyline_distance(p, path));
    return worst;
  }
  const std::size_t segments = path.size() - 1;
  for (std::size_t index = 0; index < points.size(); ++index) {
    const PointD p = points[index];
    if (hint >= segments) hint = 0;
    // The least squared distance so far; the scan stops once it proves p cannot raise `worst`
    // (sqrt is monotone, so sqrt(least) <= worst bounds p's distance by worst).
    double least = INFINITY; // as polyline_distance starts (a NaN distance is passed over)
    least = std::min(least, segment_distance2(p, path[hint], path[hint + 1]));
    const double worst2 = worst * worst;
    auto settled = [&] { return least <= worst2 && std::sqrt(least) <= worst; };
    if (settled()) continue;
    bool stopped = false;
    for (std::size_t i = 0; i < segments && !stopped; ++i) {
      const double d2 = segment_distance2(p, path[i], path[i + 1]);
      if (d2 < least) {
        least = d2;
        hint = i;
        stopped = settled();
      }
    }
    if (stopped) continue;
    // Every segment seen: least is p's squared distance, as polyline_distance takes it.
    if (const double d = std::sqrt(least); d > worst) {
      worst = d;
      if (raised_at != nullptr) *raised_at = index;
    }
    if (worst >= stop_at) return worst;
  }
  return worst;
}

namespace {

constexpr std::size_t kBlockSegments = 8; // stroke segments per pruning block
// Rounding room of the block test: a segment's proposed distance (distance_kernel.hpp) is within
// 26 u d + 12 u L of its true distance d (u = 2^-53, L its length: each difference is rounded
// once, the cross product's cancellation is at most 8 u |p - s| |s - t| with |p - s| <= d + L,
// and a foot proposed just past an end moves it by at most 4 u |p - s|), and the box's distance
// is within 3 u of its own; this room is over 400 times that.
constexpr double kRoom = 1e-12;

} // namespace

FitObjective::FitObjective(const PreparedStroke& stroke, bool use_key_points)
    : stroke_(stroke), use_key_points_(use_key_points) {
  const std::vector<PointD>& pts = stroke.points;
  if (!use_key_points || pts.size() < 2) return;
  for (std::size_t first = 0; first + 1 < pts.size(); first += kBlockSegments) {
    Block b{first, std::min(first + kBlockSegments, pts.size() - 1), pts[first], pts[first], 0.0};
    for (std::size_t i = first; i < b.end; ++i) {
      const PointD q = pts[i + 1];
      b.lo = {std::min(b.lo.x, q.x), std::min(b.lo.y, q.y)};
      b.hi = {std::max(b.hi.x, q.x), std::max(b.hi.y, q.y)};
      b.longest = std::max(b.longest, distance(pts[i], q));
    }
    blocks_.push_back(b);
  }
}

// raise_to_polyline_distance for one key point against the stroke, skipping blocks whose box is
// farther than the nearest segment so far by more than any rounding: those hold no segment whose
// proposed distance is below it, so the least distance, and the value, are the same.
double FitObjective::raise_to_stroke_distance(PointD v, double worst, std::size_t& hint) const {
  const std::vector<PointD>& pts = stroke_.points;
  if (blocks_.empty()) return raise_to_polyline_distance({&v, 1}, pts, worst, hint);
  if (hint + 1 >= pts.size()) hint = 0;
  double least = INFINITY;
  least = std::min(least, segment_distance2(v, pts[hint], pts[hint + 1]));
  const double worst2 = worst * worst;
  auto settled = [&] { return least <= worst2 && std::sqrt(least) <= worst; };
  if (settled()) return worst;
  for (const Block& b : blocks_) {
    const double bx = std::max({b.lo.x - v.x, v.x - b.hi.x, 0.0});
    const double by = std::max({b.lo.y - v.y, v.y - b.hi.y, 0.0});
    const double box = std::sqrt(bx * bx + by * by);
    if (box * (1.0 - kRoom) - kRoom * b.longest > std::sqrt(least) * (1.0 + kRoom)) continue;
    for (std::size_t i = b.first; i < b.end; ++i) {
      const double d2 = segment_distance2(v, pts[i], pts[i + 1]);
      if (d2 < least) {
        least = d2;
        hint = i;
        if (settled()) return worst;
      }
    }
  }
  return std::max(worst, std::sqrt(least));
}

double FitObjective::operator()(const CleanShape& shape, double stop_at) {
  double worst = 0.0;
  const std::vector<PointD>& fit = stroke_.fit_points;
  if (shape.kind == CleanShape::Kind::kPolyline) {
    if (raised_at_ < fit.size()) {
      worst = raise_to_polyline_distance({&fit[raised_at_], 1}, shape.path, worst, raised_hint_);
      if (worst >= stop_at) return worst;
    }
    worst = raise_to_polyline_distance(fit, shape.path, worst, fit_hint_, stop_at, &raised_at_);
  } else {
    worst = max_distance(fit, shape);
  }
  if (!use_key_points_ || worst >= stop_at) return worst;
  std::size_t k = 0;
  auto key = [&](PointD v) {
    if (key_hints_.size() <= k) key_hints_.resize(k + 1, 0);
    worst = raise_to_stroke_distance(v, worst, key_hints_[k++]);
  };
  if (shape.kind == CleanShape::Kind::kPolyline) {
    for (const PointD& v : shape.path) {
      key(v);
      if (worst >= stop_at) return worst;
    }
  } else if (!shape.full_curve()) {
    key(shape.at(shape.t0));
    key(shape.at(shape.t0 + shape.sweep));
  }
  return worst;
}

double fit_objective(const PreparedStroke& stroke, const CleanShape& shape, bool use_key_points) {
  return FitObjective(stroke, use_key_points)(shape);
}

Refinement refine_minimax(const PreparedStroke& stroke, const std::vector<double>& params,
                          const ShapeBuilder& build, double initial_step, bool use_key_points) {
  // One objective for the whole search: its hints follow the small steps of the shape.
  FitObjective objective(stroke, use_key_points);
  // A trial is kept only when it beats the best: its evaluation stops once it cannot.
  auto evaluate = [&](const std::vector<double>& p, double stop_at) {
    const std::optional<CleanShape> shape = build(p);
    return shape ? objective(*shape, stop_at) : INFINITY;
  };
  Refinement best{params, evaluate(params, INFINITY)};
  // A trial must gain more than rounding could: where a step leaves the farthest point where it
  // is (a plateau of the minimax), the values tie but for their last bits, which differ with the
  // drawing's origin and unit; taking such a "gain" would make the answer depend on them.
  const double least_gain = kLeastRefineGain * stroke.size;
  const auto beats = [&least_gain](double value, double best_value) {
    return value < best_value - least_gain;
  };
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
        const double value = evaluate(trial, best.objective - least_gain);
        ++evaluations;
        if (beats(value, best.objective)) {
          // Keep moving that way while it helps (a cheap pattern move).
          best = {trial, value};
          trial[i] += sign * step;
          const double further = evaluate(trial, best.objective - least_gain);
          ++evaluations;
          if (beats(further, best.objective)) best = {std::move(trial), further};
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
