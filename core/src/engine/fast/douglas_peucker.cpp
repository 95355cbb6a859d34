#include "douglas_peucker.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "certified.hpp"

namespace penshape::fast {
namespace {

// Squared distance from p to the segment [a, b] in doubles: a proposal only (the kept vertices
// are certified afterwards), so the plain formula serves, without the shared kernel's sqrt.
double squared_segment_distance(DPt p, DPt a, DPt b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double px = p.x - a.x, py = p.y - a.y;
  const double len2 = dx * dx + dy * dy;
  const double t = len2 > 0.0 ? std::clamp((px * dx + py * dy) / len2, 0.0, 1.0) : 0.0;
  const double ex = px - t * dx, ey = py - t * dy;
  return ex * ex + ey * ey;
}

// Perpendicular-distance Douglas-Peucker on the open chain ring[i..j] (indices modulo n).
void douglas_peucker(const IRing& ring, std::size_t i, std::size_t j, double tol,
                     std::vector<char>& keep) {
  const std::size_t n = ring.size();
  if ((j + n - i) % n < 2) return;
  const DPt a = to_d(ring[i % n]);
  const DPt b = to_d(ring[j % n]);
  double worst = -1.0;
  std::size_t worst_k = i;
  for (std::size_t k = i + 1; k < j; ++k) {
    const double d = squared_segment_distance(to_d(ring[k % n]), a, b);
    if (d > worst) {
      worst = d;
      worst_k = k;
    }
  }
  // A negative tolerance keeps every vertex, as the distance itself would.
  if (worst > (tol < 0.0 ? -1.0 : tol * tol)) {
    keep[worst_k % n] = 1;
    douglas_peucker(ring, i, worst_k, tol, keep);
    douglas_peucker(ring, worst_k, j, tol, keep);
  }
}

// Indices of the vertices Douglas-Peucker keeps, increasing, starting with 0.
std::vector<std::size_t> kept_indices(const IRing& ring, double tol) {
  const std::size_t n = ring.size();
  std::vector<std::size_t> idx;
  if (n <= 4) {
    for (std::size_t k = 0; k < n; ++k) idx.push_back(k);
    return idx;
  }
  // Split the closed ring at vertex 0 and at the vertex farthest from it.
  std::size_t far = 0;
  std::int64_t best = -1;
  for (std::size_t k = 1; k < n; ++k) {
    const std::int64_t d =
        std::max(std::abs(ring[k].x - ring[0].x), std::abs(ring[k].y - ring[0].y));
    if (d > best) {
      best = d;
      far = k;
    }
  }
  std::vector<char> keep(n, 0);
  keep[0] = keep[far] = 1;
  douglas_peucker(ring, 0, far, tol, keep);
  douglas_peucker(ring, far, n, tol, keep);
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
