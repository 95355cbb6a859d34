#pragma once
// Douglas–Peucker, written once. The callers differ in what they certify, so the kernel takes the
// two things that differ as parameters: how far a point is from a chord (doubles, squared or
// not: a proposal) and whether a chord may replace the points between its ends (the caller's
// test, where a certificate may decide). Indices only: callers map them to points, modulo a
// ring's size where the chain wraps. Internal to core.
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace penshape::detail {

// Marks keep[k] = 1 for the points of the chain first..last that Douglas–Peucker keeps (the ends
// are the caller's to mark). For each chord (a, b) it finds the first point k in (a, b) with the
// largest measure(k, a, b); if chord_holds(a, b, that largest measure) the points between are
// dropped, else k is kept and both halves are simplified. Iterative: no recursion depth limit.
// The kept set does not depend on the order the halves are visited in.
template <typename Measure, typename ChordHolds>
void douglas_peucker(std::size_t first, std::size_t last, Measure&& measure,
                     ChordHolds&& chord_holds, std::vector<char>& keep) {
  using NT = decltype(measure(first, first, last));
  std::vector<std::pair<std::size_t, std::size_t>> todo{{first, last}};
  while (!todo.empty()) {
    const auto [a, b] = todo.back();
    todo.pop_back();
    if (b <= a + 1) continue;
    NT worst = std::numeric_limits<NT>::lowest();
    std::size_t at = a;
    for (std::size_t k = a + 1; k < b; ++k) {
      const NT d = measure(k, a, b);
      if (d > worst) {
        worst = d;
        at = k;
      }
    }
    if (chord_holds(a, b, worst)) continue;
    if (at == a) at = a + 1; // no measure compared (NaN): keep a point rather than loop
    keep[at] = 1;
    todo.emplace_back(a, at);
    todo.emplace_back(at, b);
  }
}

// The first vertex k in 1..n-1 with the largest spread(k) (how far vertex k is from vertex 0, in
// the caller's metric), or 0 when none is above -1: where a closed ring is split in two chains.
template <typename Spread>
std::size_t farthest_from_first(std::size_t n, Spread&& spread) {
  using NT = decltype(spread(n));
  std::size_t far = 0;
  NT best = -1;
  for (std::size_t k = 1; k < n; ++k) {
    const NT d = spread(k);
    if (d > best) {
      best = d;
      far = k;
    }
  }
  return far;
}

// Douglas–Peucker on a closed ring of n vertices split at vertex 0 and vertex `far`: the chains
// 0..far and far..n (index n is vertex 0 again, so measure must map indices modulo n). Returns
// the keep marks, vertices 0 and far always kept.
template <typename Measure, typename ChordHolds>
std::vector<char> douglas_peucker_ring(std::size_t n, std::size_t far, Measure&& measure,
                                       ChordHolds&& chord_holds) {
  std::vector<char> keep(n, 0);
  if (n == 0) return keep;
  keep[0] = keep[far] = 1;
  douglas_peucker(0, far, measure, chord_holds, keep);
  douglas_peucker(far, n, measure, chord_holds, keep);
  return keep;
}

} // namespace penshape::detail
