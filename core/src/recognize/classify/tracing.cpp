// The stroke's progress along a clean shape's path (tracing.hpp).
#include "recognize/classify/tracing.hpp"

#include <cmath>

#include "recognize/fitting/geometry.hpp"
#include "recognize/fitting/path_turn.hpp"

namespace penshape::recognize_detail {
namespace {

// The length of `path` (closed: steps wrap round) over which `stroke` runs against its net
// direction along it.
double back_length(const std::vector<PointD>& stroke, const ArcLengthPath& path, bool closed) {
  if (stroke.size() < 2) return 0.0;
  const double total = path.length();
  std::vector<double> steps;
  double previous = path.nearest(stroke.front()).at, net = 0;
  for (std::size_t i = 1; i < stroke.size(); ++i) {
    const double t = path.nearest(stroke[i]).at;
    double step = t - previous;
    if (closed) step -= total * std::round(step / total); // the shorter way round
    steps.push_back(step);
    net += step;
    previous = t;
  }
  double back = 0;
  for (const double step : steps) back += net >= 0 ? std::max(0.0, -step) : std::max(0.0, step);
  return back;
}

} // namespace

double backtrack_share(const std::vector<PointD>& stroke, const std::vector<PointD>& path) {
  return backtrack_share(std::vector<std::vector<PointD>>{stroke}, path);
}

double backtrack_share(const std::vector<std::vector<PointD>>& strokes,
                       const std::vector<PointD>& path) {
  if (path.size() < 2) return 0.0;
  const ArcLengthPath along(path);
  const double total = along.length();
  if (!(total > 0)) return 0.0;
  const bool closed = closed_path(path);
  double back = 0;
  for (const std::vector<PointD>& stroke : strokes) back += back_length(stroke, along, closed);
  return back / total;
}

bool closed_path(const std::vector<PointD>& path) {
  // A sampled full curve ends within rounding of its start: closed too.
  return path.size() >= 2 && distance(path.front(), path.back()) <= 1e-9 * path_length(path);
}

} // namespace penshape::recognize_detail
