// The raw outward offset path and the pruning of its covered reflex spokes (raw_offset.hpp).
//
// Why a covered spoke changes nothing. The path of one ring (vertices v_i, edges e_i = v_i v_i+1)
// is, as a 1-chain, ∂Q + Σ_i ∂R_i + Σ_convex ∂S_v: R_i = (v_i, s_i, a_i+1, v_i+1) is the
// quadrilateral edge e_i adds (s_i the last point of v_i's join, a_i+1 the first of v_i+1's, as
// rounded on the path), S_v = (v, join points) the sector of a convex join; the sides along the
// ring cancel against ∂Q and the spokes v -> s, a -> v against the sectors' radii or, at the
// other corners, form the spoke a -> v -> b itself. So the path's winding number is
// w_Q + Σ 1_R + Σ 1_S (off the boundaries). Replacing the spoke a -> v -> b by a -> b adds the
// boundary of the triangle T_v = (a, b, v): ±1 on T_v. Let z be inside the triangles of k
// dropped spokes. Each T_v lies in both quadrilaterals beside v (spoke_is_covered, and a convex
// polygon containing a triangle's corners contains the triangle), so z is in R_i for every edge
// next to those k vertices: at least k + 1 edges, since the spoke of each ring's first vertex is
// never dropped (k vertices of a cycle, not all of it, touch at least k + 1 of its edges). So
// where w_Q >= 0 and the other terms are >= 0 (each R_i and S_v a simple counterclockwise
// polygon, as the joins make them unless rounding folds a quadrilateral of an edge a few units
// long), the new winding is >= w_Q + (k + 1) - k >= 1 wherever it changed, and it only falls
// where it was positive: the positive region is unchanged.
#include "raw_offset.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace penshape::fast {
namespace {

namespace cl = ClipperLib;

IPt of(const cl::IntPoint& p) { return {p.X, p.Y}; }

// Whether p lies in the closed quadrilateral q, which must be strictly convex and
// counterclockwise (false otherwise).
bool in_convex_quad(const IPt (&q)[4], IPt p) {
  for (int i = 0; i < 4; ++i) {
    if (orientation(q[i], q[(i + 1) % 4], q[(i + 2) % 4]) <= 0) return false;
    if (orientation(q[i], q[(i + 1) % 4], p) < 0) return false;
  }
  return true;
}

// One ring's raw path: first[i] is the path index of vertex i's first join point; spoke[i]
// whether vertex i has a spoke (its points at first[i] .. first[i] + 2, v in the middle), and
// narrow[i] whether that corner turns by at most 90 degrees.
struct RingPath {
  cl::Path path;
  std::vector<std::size_t> first;
  std::vector<bool> spoke;
  std::vector<bool> narrow;
};

RingPath ring_path(const IRing& ring, double delta, double max_angle) {
  const std::size_t n = ring.size();
  std::vector<DPt> normals(n);
  for (std::size_t i = 0; i < n; ++i) {
    const IPt a = ring[i], b = ring[(i + 1) % n];
    const double dx = static_cast<double>(b.x - a.x), dy = static_cast<double>(b.y - a.y);
    const double len = std::sqrt(dx * dx + dy * dy);
    normals[i] = {dy / len, -dx / len}; // right normal: outward for a region on the left
  }
  RingPath out;
  out.path.reserve(3 * n);
  out.first.reserve(n);
  out.spoke.reserve(n);
  out.narrow.reserve(n);
  auto push = [&](const IPt& v, DPt nrm) {
    out.path.emplace_back(
        static_cast<cl::cInt>(std::llround(static_cast<double>(v.x) + delta * nrm.x)),
        static_cast<cl::cInt>(std::llround(static_cast<double>(v.y) + delta * nrm.y)));
  };
  for (std::size_t i = 0; i < n; ++i) {
    const IPt& v = ring[i];
    const DPt n0 = normals[(i + n - 1) % n], n1 = normals[i];
    const double sin_a = n0.x * n1.y - n0.y * n1.x;
    const double cos_a = n0.x * n1.x + n0.y * n1.y;
    out.first.push_back(out.path.size());
    out.spoke.push_back(sin_a < 0.0);
    out.narrow.push_back(cos_a >= 0.0);
    if (sin_a < 0.0) { // reflex: the spoke through v (the union removes it)
      push(v, n0);
      out.path.emplace_back(v.x, v.y);
      push(v, n1);
      continue;
    }
    const double a = std::atan2(sin_a, cos_a);
    const int steps = std::max(1, static_cast<int>(std::ceil(a / max_angle)));
    for (int k = 0; k <= steps; ++k) {
      const double t = a * k / steps;
      const double c = std::cos(t), s = std::sin(t);
      push(v, {n0.x * c - n0.y * s, n0.x * s + n0.y * c});
    }
  }
  return out;
}

// The path without the vertex points of the spokes `spokes` drops (never the first vertex's:
// see above; kNarrow keeps it too).
cl::Path without_spokes(const IRing& ring, const RingPath& rp, Spokes spokes) {
  const std::size_t n = ring.size();
  const cl::Path& path = rp.path;
  auto last_of = [&](std::size_t i) { // the last join point of vertex i
    return i + 1 < n ? rp.first[i + 1] - 1 : path.size() - 1;
  };
  std::vector<bool> drop(path.size(), false);
  for (std::size_t i = 1; i < n; ++i) {
    if (!rp.spoke[i]) continue;
    const std::size_t at = rp.first[i];
    const std::size_t prev = i - 1, next = (i + 1) % n;
    drop[at + 1] = (spokes == Spokes::kNarrow && rp.narrow[i]) ||
                   spoke_is_covered(ring[prev], of(path[last_of(prev)]), of(path[at]), ring[i],
                                    of(path[at + 2]), of(path[rp.first[next]]), ring[next]);
  }
  cl::Path out;
  out.reserve(path.size());
  for (std::size_t k = 0; k < path.size(); ++k) {
    if (!drop[k]) out.push_back(path[k]);
  }
  return out;
}

} // namespace

bool spoke_is_covered(IPt u, IPt s, IPt a, IPt v, IPt b, IPt e, IPt w) {
  const IPt r0[4] = {u, s, a, v};
  const IPt r1[4] = {v, b, e, w};
  return in_convex_quad(r0, b) && in_convex_quad(r1, a);
}

cl::Paths raw_outward(const IRings& rings, double delta, double arc_tolerance, Spokes spokes) {
  const double max_angle = 2.0 * std::acos(std::max(-1.0, 1.0 - arc_tolerance / delta));
  cl::Paths raw;
  raw.reserve(rings.size());
  for (const IRing& ring : rings) {
    if (ring.size() < 3) continue;
    RingPath rp = ring_path(ring, delta, max_angle);
    raw.push_back(spokes == Spokes::kKeep ? std::move(rp.path) : without_spokes(ring, rp, spokes));
  }
  return raw;
}

} // namespace penshape::fast
