// Windowed Douglas-Peucker (see thin_path.hpp; the proof of H(A, A') <= tau is in recognize.hpp).
#include "recognize/fitting/thin_path.hpp"

#include <algorithm>

#include "geometry/distance_kernel.hpp"
#include "geometry/douglas_peucker.hpp"

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

} // namespace

std::vector<PointD> thin_path(std::span<const PointD> path, double tau) {
  if (!(tau > 0.0) || path.size() <= 2) return {path.begin(), path.end()};
  std::vector<char> keep(path.size(), 0);
  const std::size_t last = path.size() - 1;
  for (std::size_t a = 0; a < last; a += kThinWindow) {
    const std::size_t b = std::min(a + kThinWindow, last);
    keep[a] = keep[b] = 1;
    // Doubles propose the farthest point; a chord holds only when the kernel certifies it.
    detail::douglas_peucker(
        a, b,
        [&](std::size_t k, std::size_t i, std::size_t j) {
          return segment_distance(path[k], path[i], path[j]);
        },
        [&](std::size_t i, std::size_t j, double worst) {
          return worst <= tau && all_within(path, i, j, tau);
        },
        keep);
  }
  std::vector<PointD> out;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (keep[i]) out.push_back(path[i]);
  }
  return out;
}

} // namespace penshape::recognize_detail
