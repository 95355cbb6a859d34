// The reference engine: APPROXDECIDE (deconstructing-approximate-offsets, Algorithms 2-4)
// literally, on exact CGAL regions. Interior approximation first (YES with P = Π̂), then the
// exterior one (NO), else UNDECIDED. The cancel hook is checked between CGAL operations (per
// polygon of a Minkowski sum and between the steps), so its latency is one CGAL operation:
// ~0.1-0.5 s on the 1,881-vertex Kazakhstan polygon.
#include <algorithm>

#include "engine/engines.hpp"
#include "geometry/exact_region.hpp"
#include "geometry/interior_point.hpp"
#include "penshape/core/disk_approximation.hpp"

namespace penshape::detail {
namespace {

struct Disks {
  Ring offset_eps;   // D̂_ε
  Ring inset_r;      // D̂_r
  Ring offset_r_eps; // D̂_{r+ε}
  std::size_t largest = 0;
};

// Interior (Algorithm 2): offsets by D̄_{s-δ,s}, insets by D̄_{s,s+δ}; every step shrinks.
Disks interior_disks(const DeconstructParams& p, std::size_t max_vertices) {
  const Rational& r = p.radius;
  const Rational& e = p.tolerance;
  const Rational& d = p.precision;
  Disks k{disk_approximation(e - d, e, max_vertices), disk_approximation(r, r + d, max_vertices),
          disk_approximation(r + e - d, r + e, max_vertices), 0};
  k.largest = std::max({k.offset_eps.size(), k.inset_r.size(), k.offset_r_eps.size()});
  return k;
}

// Exterior (Algorithm 3): offsets by D̄_{s,s+δ}, insets by D̄_{s-δ,s}; every step grows.
Disks exterior_disks(const DeconstructParams& p, std::size_t max_vertices) {
  const Rational& r = p.radius;
  const Rational& e = p.tolerance;
  const Rational& d = p.precision;
  Disks k{disk_approximation(e, e + d, max_vertices), disk_approximation(r - d, r, max_vertices),
          disk_approximation(r + e, r + e + d, max_vertices), 0};
  k.largest = std::max({k.offset_eps.size(), k.inset_r.size(), k.offset_r_eps.size()});
  return k;
}

struct Pass {
  ExactRegion pi;      // Π̂
  ExactRegion q_prime; // Q̂'
  bool covers = false; // Q ⊆ Q̂'
};

Pass run_pass(const ExactRegion& q, const Disks& k, const CancelHook& cancel) {
  const ExactRegion q_eps = q.minkowski_sum(k.offset_eps, cancel); // (1)
  Pass pass;
  pass.pi = q_eps.inset(k.inset_r, cancel);                     // (2)
  pass.q_prime = pass.pi.minkowski_sum(k.offset_r_eps, cancel); // (3)
  if (cancel && cancel()) throw Cancelled();
  pass.covers = pass.q_prime.contains(q); // (4)
  return pass;
}

} // namespace

DeconstructResult decide_reference(const PolygonSet& q, const DeconstructParams& params,
                                   const CancelHook& cancel, const DeconstructLimits& limits) {
  DeconstructResult result;
  result.engine = EngineKind::kReference;
  result.params = params;
  const ExactRegion region = ExactRegion::from(q);

  const Disks inner = interior_disks(params, limits.max_disk_vertices);
  const Disks outer = exterior_disks(params, limits.max_disk_vertices);
  result.disk_vertices = std::max(inner.largest, outer.largest);

  Pass interior = run_pass(region, inner, cancel);
  if (interior.covers) {
    // Lemma 9: Π̂ ⊆ Π and Q ⊆ offset(Π̂, r + ε), so P = Π̂ is a solution with H <= ε.
    result.answer = Answer::kYes;
    result.solution = interior.pi.to_polygon_set();
    result.hausdorff_bound = params.tolerance;
    return result;
  }
  const Pass exterior = run_pass(region, outer, cancel);
  // Lemma 12: Q̂' ⊇ Q' exactly, so Q ⊄ Q̂' rules out every solution.
  result.answer = exterior.covers ? Answer::kUndecided : Answer::kNo;
  if (result.answer == Answer::kNo) {
    // A point inside Q \ Q̂' is outside offset(Π, r + ε): the witness `penshape verify` checks.
    result.no_witness = interior_point(region.minus(exterior.q_prime).to_polygon_set());
  }
  return result;
}

} // namespace penshape::detail
