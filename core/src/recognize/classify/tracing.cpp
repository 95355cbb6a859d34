// The stroke's progress along a clean shape's path (tracing.hpp).
#include "recognize/classify/tracing.hpp"

#include <cmath>

#include "recognize/fitting/geometry.hpp"

namespace penshape::recognize_detail {
namespace {

// Arc length along `path` (with cumulative lengths `at`) of the point of `path` nearest to p.
double nearest_arc_length(PointD p, const std::vector<PointD>& path,
                          const std::vector<double>& at) {
  double best = INFINITY, out = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double d = segment_distance2(p, path[i], path[i + 1]);
    if (d >= best) continue;
    best = d;
    const PointD e = path[i + 1] - path[i];
    const double len2 = dot(e, e);
    const double u = len2 > 0 ? std::clamp(dot(p - path[i], e) / len2, 0.0, 1.0) : 0.0;
    out = at[i] + u * (at[i + 1] - at[i]);
  }
  return out;
}

} // namespace

double backtrack_share(const std::vector<PointD>& stroke, const std::vector<PointD>& path) {
  if (path.size() < 2 || stroke.size() < 2) return 0.0;
  std::vector<double> at{0.0};
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    at.push_back(at.back() + distance(path[i], path[i + 1]));
  const double total = at.back();
  if (!(total > 0)) return 0.0;
  // A sampled full curve ends within rounding of its start: closed too.
  const bool closed = distance(path.front(), path.back()) <= 1e-9 * total;
  std::vector<double> steps;
  double previous = nearest_arc_length(stroke.front(), path, at), net = 0;
  for (std::size_t i = 1; i < stroke.size(); ++i) {
    const double t = nearest_arc_length(stroke[i], path, at);
    double step = t - previous;
    if (closed) step -= total * std::round(step / total); // the shorter way round
    steps.push_back(step);
    net += step;
    previous = t;
  }
  double back = 0;
  for (const double step : steps) back += net >= 0 ? std::max(0.0, -step) : std::max(0.0, step);
  return back / total;
}

} // namespace penshape::recognize_detail
