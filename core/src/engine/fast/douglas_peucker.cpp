#include "douglas_peucker.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "certified.hpp"
#include "geometry/douglas_peucker.hpp"

namespace penshape::fast {
namespace {

// Indices of the vertices Douglas-Peucker keeps (geometry/douglas_peucker.hpp), increasing,
// starting with 0: the ring split at vertex 0 and the vertex farthest from it, squared distances
// in doubles (a proposal only: the kept vertices are certified afterwards).
std::vector<std::size_t> kept_indices(const IRing& ring, double tol) {
  const std::size_t n = ring.size();
  std::vector<std::size_t> idx;
  if (n <= 4) {
    for (std::size_t k = 0; k < n; ++k) idx.push_back(k);
    return idx;
  }
  const std::size_t far = detail::farthest_from_first(n, [&](std::size_t k) {
    return std::max(std::abs(ring[k].x - ring[0].x), std::abs(ring[k].y - ring[0].y));
  });
  // A negative tolerance keeps every vertex, as the distance itself would.
  const double tol2 = tol < 0.0 ? -1.0 : tol * tol;
  // The vertices as doubles once (exact: |coordinates| <= 2^31), index n being vertex 0 again:
  // the kernel measures O(n log n) times, each without a conversion or a division.
  thread_local std::vector<DPt> pts;
  pts.clear();
  pts.reserve(n + 1);
  for (const IPt& p : ring) pts.push_back(to_d(p));
  pts.push_back(pts.front());
  const std::vector<char> keep = detail::douglas_peucker_ring(
      n, far,
      [&](std::size_t k, std::size_t i, std::size_t j) {
        return detail::proposed_squared_distance(pts[k], pts[i], pts[j]);
      },
      [&](std::size_t, std::size_t, double worst) { return !(worst > tol2); });
  for (std::size_t k = 0; k < n; ++k) {
    if (keep[k]) idx.push_back(k);
  }
  return idx;
}

} // namespace

IRing simplify_ring(const IRing& ring, double tolerance) {
  IRing out;
  for (const std::size_t k : kept_indices(ring, tolerance)) out.push_back(ring[k]);
  return out;
}

std::optional<IRings> simplify_rings_checked(const IRings& rings, double tolerance) {
  IRings out;
  out.reserve(rings.size());
  for (const IRing& ring : rings) {
    // Proposed half a unit tighter than the bound we certify (as before the certified check).
    const std::vector<std::size_t> idx = kept_indices(ring, tolerance - 0.5);
    IRing s;
    for (const std::size_t k : idx) s.push_back(ring[k]);
    if (s.size() < 3 || (twice_area(s) > 0) != (twice_area(ring) > 0)) return std::nullopt;
    // Every dropped vertex within the tolerance of the chord that replaced it (certified).
    for (std::size_t c = 0; c < idx.size(); ++c) {
      const std::size_t from = idx[c];
      const std::size_t to = c + 1 < idx.size() ? idx[c + 1] : ring.size();
      const IPt a = ring[from], b = ring[to % ring.size()];
      for (std::size_t k = from + 1; k < to; ++k) {
        if (compare_distance(at_point(ring[k]), a, b, tolerance) > 0) return std::nullopt;
      }
    }
    out.push_back(std::move(s));
  }
  return out;
}

} // namespace penshape::fast
