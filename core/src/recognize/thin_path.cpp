// Windowed Douglas-Peucker (see thin_path.hpp; the proof of H(A, A') <= tau is in recognize.hpp).
#include "thin_path.hpp"

#include <algorithm>
#include <utility>

namespace penshape::recognize_detail {
namespace {

// Marks the points of path[first..last] to keep so that every unmarked point is within tau of
// the chord of the nearest marked points around it (iterative, no recursion depth limit).
void douglas_peucker(std::span<const PointD> path, std::size_t first, std::size_t last, double tau,
                     std::vector<char>& keep) {
  std::vector<std::pair<std::size_t, std::size_t>> todo{{first, last}};
  while (!todo.empty()) {
    const auto [a, b] = todo.back();
    todo.pop_back();
    if (b <= a + 1) continue;
    double worst = -1.0;
    std::size_t at = a;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = segment_distance(path[i], path[a], path[b]);
      if (d > worst) {
        worst = d;
        at = i;
      }
    }
    if (worst <= tau) continue; // every point of (a, b) within tau of the chord: drop them
    keep[at] = 1;
    todo.emplace_back(a, at);
    todo.emplace_back(at, b);
  }
}

} // namespace

std::vector<PointD> thin_path(std::span<const PointD> path, double tau) {
  if (!(tau > 0.0) || path.size() <= 2) return {path.begin(), path.end()};
  std::vector<char> keep(path.size(), 0);
  const std::size_t last = path.size() - 1;
  for (std::size_t a = 0; a < last; a += kThinWindow) {
    const std::size_t b = std::min(a + kThinWindow, last);
    keep[a] = keep[b] = 1;
    douglas_peucker(path, a, b, tau, keep);
  }
  std::vector<PointD> out;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (keep[i]) out.push_back(path[i]);
  }
  return out;
}

} // namespace penshape::recognize_detail
