#include "yes_certificate.hpp"

#include <algorithm>

#include "grid_frame.hpp"
#include "level_set_check.hpp"

namespace penshape::fast {
namespace {

// Covers the double rounding of r and eps in grid units (relative error 2^-53 on <= 2^31).
constexpr double kParamRounding = 1.0 / 256.0;

// d(v, region) <= bound, conservatively (inside counts as distance 0).
bool within(const SegmentIndex& region, IPt v, double bound) {
  if (region.winding(v) > 0) return true;
  return region.distance(to_d(v), bound + 1.0) <= bound;
}

} // namespace

bool verify_yes(const YesCheckInput& in, const IRegion& p, const CancelHook& cancel) {
  if (p.empty()) return false;
  const SegmentIndex pi(flatten(p), in.radius / 2.0);
  if (!is_certifiable_region(pi)) return false;

  const double level_a = in.tolerance - in.eta - kParamRounding;    // <= eps - η
  const double level_b = in.radius + in.tolerance - kParamRounding; // <= r + eps

  // (A2) no component of P lies wholly where d(·, Q_s) > level_a (in.q is Q_s or Q̃).
  for (const IPolygon& poly : p) {
    if (!within(*in.q, poly.outer.front(), level_a - kDistanceSlack)) return false;
  }
  // (B2) no component of Q lies wholly where d(·, P) > level_b (its vertex is within η).
  for (const IPt& v : in.q_component_vertices) {
    if (!within(pi, v, level_b - kInputRounding - kDistanceSlack)) return false;
  }
  // (A1) the level set {d(·, Q_s) = level_a} keeps distance > r from P.
  if (!level_set_avoids({in.q, level_a, &pi, in.radius + kParamRounding, in.max_sagitta}, cancel)) {
    return false;
  }
  // (B1) the level set {d(·, P) = level_b} stays outside Q: farther than η0 from Q̃ (the
  // unsimplified grid input, so the simplification does not eat into this margin).
  return level_set_avoids(
      {&pi, level_b, in.q_grid, std::max(1.0, kInputRounding + kParamRounding), in.max_sagitta},
      cancel);
}

} // namespace penshape::fast
