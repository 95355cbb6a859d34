#pragma once
// The touching/crossing test input validation used before the Shamos–Hoey sweep (kept here only
// as scale_bench's baseline): sort edges by x, compare exactly every pair whose x-ranges and
// y-ranges overlap. O(n·k) for k edges over a vertical line: up to O(n²) on a comb.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/exact_predicates.hpp"

namespace penshape::bench {

// True when two non-neighbouring edges of the ring (or two neighbours folding back) meet.
inline bool former_ring_has_contact(const Ring& ring) {
  using detail::FilteredPoint;
  const auto widen_down = [](double v) {
    return v - 1e-15 * std::abs(v) - std::numeric_limits<double>::min();
  };
  const auto widen_up = [](double v) {
    return v + 1e-15 * std::abs(v) + std::numeric_limits<double>::min();
  };
  struct Edge {
    std::size_t index;
    double xmin, xmax, ymin, ymax;
  };
  const std::size_t n = ring.size();
  std::vector<FilteredPoint> pts;
  for (const auto& v : ring) pts.push_back(detail::filtered(v));
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = pts[i];
    const auto& q = pts[(i + 1) % n];
    edges.push_back({i, widen_down(std::min(p.x, q.x)), widen_up(std::max(p.x, q.x)),
                     widen_down(std::min(p.y, q.y)), widen_up(std::max(p.y, q.y))});
  }
  std::sort(edges.begin(), edges.end(),
            [](const Edge& a, const Edge& b) { return a.xmin < b.xmin; });
  std::vector<const Edge*> active;
  for (const Edge& e : edges) {
    std::erase_if(active, [&](const Edge* a) { return a->xmax < e.xmin; });
    for (const Edge* a : active) {
      if (a->ymax < e.ymin || e.ymax < a->ymin) continue;
      if ((a->index + 1) % n == e.index || (e.index + 1) % n == a->index) continue;
      if (detail::segments_intersect(pts[a->index], pts[(a->index + 1) % n], pts[e.index],
                                     pts[(e.index + 1) % n])) {
        return true;
      }
    }
    active.push_back(&e);
  }
  return false;
}

} // namespace penshape::bench
