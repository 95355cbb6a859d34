// The fast engine: APPROXDECIDE's interior and exterior chains on an integer grid with Clipper
// (candidates only), then exact-grid certificates for the answer (README.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "../engines.hpp"
#include "clipper_stage.hpp"
#include "douglas_peucker.hpp"
#include "grid_frame.hpp"
#include "level_set_check.hpp"
#include "no_certificate.hpp"
#include "segment_index.hpp"
#include "yes_certificate.hpp"

namespace penshape::detail {
namespace {

using namespace penshape::fast;

// Budget of the working precision delta (grid units d), see README.md: every stage of each chain
// loses less than d (the paper allows d per stage, Theorems 11 and 13): stage 1 loses
// 2·margin + input + arc = 7d/8, stage 2 2·margin + arc = 5d/8, and the YES test of stage 3 is
// exact up to the simplification of P and the input (d/16 + d/4).
struct Budget {
  double margin;        // slack left for the certificates on each side
  double arc_tolerance; // chord depth of the round joins
  double simplify;      // Douglas-Peucker tolerance for P
  double input;         // Douglas-Peucker tolerance for the copy of Q̃ the chains offset
};

Budget budget(double d) { return {d / 16.0, d / 2.0, d / 16.0, d / 4.0}; }

void check_cancel(const CancelHook& cancel) {
  if (cancel && cancel()) throw Cancelled();
}

// One offset stage, with the disk-size limit enforced before Clipper runs.
IRegion offset_stage(const IRings& rings, double delta, double tol, const DeconstructLimits& limits,
                     std::size_t& disk_vertices) {
  const double steps = std::ceil(round_join_steps(delta, tol));
  if (steps > static_cast<double>(limits.max_disk_vertices)) {
    throw InvalidInput("fast engine: a disk of radius " + std::to_string(std::fabs(delta)) +
                       " grid units at tolerance " + std::to_string(tol) + " needs " +
                       std::to_string(static_cast<long long>(steps)) +
                       " vertices, over the limit of " + std::to_string(limits.max_disk_vertices) +
                       " (precision too fine for the radius)");
  }
  disk_vertices = std::max(disk_vertices, static_cast<std::size_t>(steps));
  return offset_round(rings, delta, tol);
}

PolygonSet to_polygon_set(const GridFrame& frame, const IRegion& region) {
  PolygonSet out;
  for (const IPolygon& poly : region) {
    PolygonWithHoles pw;
    for (const IPt& p : poly.outer) pw.outer.push_back(frame.exact(p));
    for (const IRing& hole : poly.holes) {
      Ring h;
      for (const IPt& p : hole) h.push_back(frame.exact(p));
      pw.holes.push_back(std::move(h));
    }
    out.polygons.push_back(std::move(pw));
  }
  return out;
}

// Points of Q̃ \ Q̂' (exterior chain) worth trying as NO witnesses: inside Q̃ away from its
// boundary, farthest from Q̂' first. Vertices of the difference often sit on ∂Q̃, so we also
// try points pulled from each vertex towards the piece's centroid.
std::vector<IPt> witness_candidates(const IRegion& diff, const SegmentIndex& q_index,
                                    const SegmentIndex& q_hat_prime) {
  std::vector<std::pair<double, IPt>> scored;
  const double clear = kInputRounding + 2.0;
  for (const IPolygon& poly : diff) {
    double cx = 0, cy = 0;
    for (const IPt& p : poly.outer) {
      cx += static_cast<double>(p.x);
      cy += static_cast<double>(p.y);
    }
    const double n = static_cast<double>(poly.outer.size());
    const DPt centre{cx / n, cy / n};
    std::vector<DPt> pts{centre};
    for (const IPt& p : poly.outer) {
      for (const double t : {1.0 / 256, 1.0 / 64, 1.0 / 16, 1.0 / 4, 1.0 / 2}) {
        pts.push_back({static_cast<double>(p.x) + t * (centre.x - static_cast<double>(p.x)),
                       static_cast<double>(p.y) + t * (centre.y - static_cast<double>(p.y))});
      }
    }
    for (const DPt& d : pts) {
      const IPt g{std::llround(d.x), std::llround(d.y)};
      if (q_index.winding(g) <= 0 || q_index.distance(to_d(g), clear) < clear) continue;
      scored.push_back({q_hat_prime.distance(to_d(g), 1e18), g});
    }
  }
  std::sort(scored.begin(), scored.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<IPt> out;
  for (std::size_t i = 0; i < scored.size() && out.size() < 6; ++i) out.push_back(scored[i].second);
  return out;
}

} // namespace

DeconstructResult decide_fast(const PolygonSet& q, const DeconstructParams& params,
                              const CancelHook& cancel, const DeconstructLimits& limits) {
  const auto start = std::chrono::steady_clock::now();
  DeconstructResult result;
  result.engine = EngineKind::kFast;
  result.params = params;
  auto finish = [&]() {
    result.elapsed = std::chrono::duration_cast<std::chrono::nanoseconds>(
        std::chrono::steady_clock::now() - start);
    return result;
  };

  const GridFrame frame(q, params);
  const double r = frame.units(params.radius);
  const double eps = frame.units(params.tolerance);
  const double d = frame.units(params.precision);
  const Budget b = budget(d);

  const IRings q_grid = frame.round(q);
  if (q_grid.empty()) return finish();
  std::vector<IPt> q_vertices;
  for (const auto& poly : q.polygons) q_vertices.push_back(frame.round(poly.outer.front()));
  check_cancel(cancel);

  // The chains offset a simplified copy Q_s of Q̃ (H(Q_s, Q̃) <= b.input): far fewer
  // self-intersections for Clipper, and the radii below absorb the difference.
  // The chains and the YES certificate work on Q_s, a Douglas-Peucker copy of Q̃ whose distance
  // to Q̃ is checked (H(Q, Q_s) <= η + input tolerance): far fewer edges for Clipper and for the
  // level-set walk. If that copy is not simple we fall back to Q̃ itself.
  std::optional<SegmentIndex> cert_index;
  double eta = kInputRounding + b.input;
  // Narrow features can make a coarse simplification cross itself: retry finer.
  for (double tol = b.input; tol >= b.input / 8.0 && !cert_index; tol /= 2.0) {
    if (auto q_dp = simplify_rings_checked(q_grid, tol)) {
      cert_index.emplace(*q_dp, eps / 2.0);
      eta = kInputRounding + tol;
      if (!is_certifiable_region(*cert_index)) cert_index.reset();
    }
  }
  if (!cert_index) {
    eta = kInputRounding;
    cert_index.emplace(q_grid, eps / 2.0);
    // The level-set certificates need simple rings; a grid too coarse for the input's
    // features cannot certify YES (a finer precision gives a finer grid).
    if (!is_certifiable_region(*cert_index)) cert_index.reset();
  }
  const IRings q_simple = cert_index ? cert_index->rings() : q_grid;

  // Interior chain (Algorithm 2 with margins): P ⊆ inset(offset(Q̃, eps - 2m), r + 2m).
  const IRegion q_eps = offset_stage(q_simple, eps - 2 * b.margin - (eta - kInputRounding),
                                     b.arc_tolerance, limits, result.disk_vertices);
  check_cancel(cancel);
  const IRegion pi_hat = offset_stage(flatten(q_eps), -(r + 2 * b.margin + b.arc_tolerance),
                                      b.arc_tolerance, limits, result.disk_vertices);
  check_cancel(cancel);
  if (!pi_hat.empty() && cert_index) {
    const IRegion p = simplify(pi_hat, b.simplify);
    YesCheckInput in{&*cert_index, eta, q_vertices, r, eps, b.margin / 2.0};
    if (verify_yes(in, p, cancel)) {
      result.answer = Answer::kYes;
      result.solution = to_polygon_set(frame, p);
      result.hausdorff_bound = params.tolerance;
      return finish();
    }
  }
  check_cancel(cancel);

  // Exterior chain (Algorithm 3 with margins): Q̂' ⊇ offset(Π, r + eps) with room to spare.
  const IRegion q_eps_out =
      offset_stage(q_simple, eps + 2 * b.margin + (eta - kInputRounding) + b.arc_tolerance,
                   b.arc_tolerance, limits, result.disk_vertices);
  check_cancel(cancel);
  const IRegion pi_out = offset_stage(flatten(q_eps_out), -(r - 2 * b.margin), b.arc_tolerance,
                                      limits, result.disk_vertices);
  check_cancel(cancel);
  const IRegion q_prime_out =
      offset_stage(flatten(pi_out), r + eps + 2 * b.margin + b.arc_tolerance, b.arc_tolerance,
                   limits, result.disk_vertices);
  check_cancel(cancel);
  const IRegion diff = difference(q_grid, flatten(q_prime_out));
  if (diff.empty()) return finish();

  const SegmentIndex q_index(q_grid, eps / 2.0);
  const SegmentIndex outer_index(flatten(q_eps_out), r / 2.0);
  const SegmentIndex q_prime_index(flatten(q_prime_out), r / 2.0);
  NoCheckInput no{&q_index, &outer_index, r, eps, b.margin / 2.0, b.margin / 4.0};
  for (const IPt& w : witness_candidates(diff, q_index, q_prime_index)) {
    if (verify_no_witness(no, w, cancel)) {
      result.answer = Answer::kNo;
      return finish();
    }
  }
  return finish();
}

} // namespace penshape::detail
