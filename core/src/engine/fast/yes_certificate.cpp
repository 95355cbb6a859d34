#include "yes_certificate.hpp"

#include <algorithm>

#include "certified.hpp"
#include "grid_frame.hpp"
#include "level_set_check.hpp"

namespace penshape::fast {
namespace {

// d(v, region) < bound, certified (inside counts as distance 0).
bool within(const SegmentIndex& region, IPt v, double bound) {
  if (region.winding(v) > 0) return true;
  return some_edge_closer(region, at_point(v), bound);
}

} // namespace

bool verify_yes(const YesCheckInput& in, const IRegion& p, const CancelHook& cancel) {
  if (p.empty()) return false;
  const SegmentIndex pi(flatten(p), in.radius.lo / 2.0);
  if (!is_certifiable_region(pi)) return false;

  // The levels are doubles rounded down from the exact bounds, and are then taken as exact.
  const double level_a = sub_down(in.tolerance.lo, in.eta);        // <= eps - η
  const double level_b = sub_down(in.radius.lo, -in.tolerance.lo); // <= r + eps
  if (level_a <= 1.0 || level_b <= 1.0) return false;

  // (A2) no component of P lies wholly where d(·, Q_s) >= level_a (in.q is Q_s or Q̃).
  for (const IPolygon& poly : p) {
    if (!within(*in.q, poly.outer.front(), level_a)) return false;
  }
  // (B2) no component of Q lies wholly where d(·, P) >= level_b: its grid vertex is within
  // η0 = 3/4 of the true one.
  const double level_b_vertex = sub_down(level_b, kInputRounding);
  for (const IPt& v : in.q_component_vertices) {
    if (!within(pi, v, level_b_vertex)) return false;
  }
  // (A1) the level set {d(·, Q_s) = level_a} keeps distance > r (r <= radius.hi) from P.
  if (!level_set_avoids({in.q, level_a, &pi, in.radius.hi, in.max_sagitta}, cancel)) {
    return false;
  }
  // (B1) the level set {d(·, P) = level_b} stays outside Q: farther than η0 from Q̃ (the
  // unsimplified grid input, so the simplification does not eat into this margin).
  return level_set_avoids({&pi, level_b, in.q_grid, kInputRounding, in.max_sagitta}, cancel);
}

} // namespace penshape::fast
