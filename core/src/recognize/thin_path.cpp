// Windowed Douglas-Peucker (see thin_path.hpp; the proof of H(A, A') <= tau is in recognize.hpp).
#include "thin_path.hpp"

#include <algorithm>
#include <utility>

#include "geometry/distance_kernel.hpp"

namespace penshape::recognize_detail {
namespace {

// Every point of path(a, b) within tau of the chord [path[a], path[b]], decided in intervals with
// directed rounding and, where an interval cannot tell, in exact rationals (the certificate adds
// tau for H(A, A'): this is the decision it rests on).
bool all_within(std::span<const PointD> path, std::size_t a, std::size_t b, double tau) {
  std::vector<std::size_t> undecided;
  {
    const CGAL::Protect_FPU_rounding<true> rounding;
    const detail::IntervalNT t2 = CGAL::square(detail::IntervalNT(tau));
    const detail::IPoint s = detail::enclose(path[a]), e = detail::enclose(path[b]);
    for (std::size_t i = a + 1; i < b; ++i) {
      const auto d2 = detail::squared_distance_to_segment(detail::enclose(path[i]), s, e);
      if (d2 && d2->sup() <= t2.inf()) continue;
      if (d2 && d2->inf() > t2.sup()) return false;
      undecided.push_back(i);
    }
  }
  if (undecided.empty()) return true;
  const Rational t = exact(tau);
  const detail::Point2<Rational> s{exact(path[a].x), exact(path[a].y)};
  const detail::Point2<Rational> e{exact(path[b].x), exact(path[b].y)};
  for (const std::size_t i : undecided) {
    const detail::Point2<Rational> p{exact(path[i].x), exact(path[i].y)};
    if (*detail::squared_distance_to_segment(p, s, e) > t * t) return false;
  }
  return true;
}

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
    // Every point of (a, b) within tau of the chord: drop them (doubles propose, the kernel
    // decides).
    if (worst <= tau && all_within(path, a, b, tau)) continue;
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
