// The fast engine: APPROXDECIDE's interior and exterior chains on an integer grid with Clipper
// (candidates only), then exact-grid certificates for the answer (README.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "../engines.hpp"
#include "clipper_stage.hpp"
#include "douglas_peucker.hpp"
#include "fast_work.hpp"
#include "grid_frame.hpp"
#include "level_set_check.hpp"
#include "no_certificate.hpp"
#include "region_convert.hpp"
#include "segment_index.hpp"
#include "yes_certificate.hpp"

namespace penshape::detail {
namespace {

using namespace penshape::fast;

// Budget of the working precision delta (grid units d), see README.md: every stage of each chain
// loses less than d (the paper allows d per stage, Theorems 11 and 13): stage 1 loses
// 2·margin + input + arc = 13d/16, stage 2 2·margin + arc = 9d/16 (the interior chain's
// 2·margin + stage_input + arc = 13d/16), and the YES test of stage 3 is exact up to the
// simplification of P (d/32).
struct Budget {
  double margin;        // slack left for the certificates on each side
  double arc_tolerance; // chord depth of the round joins
  double simplify;      // Douglas-Peucker tolerance for P
  double input;         // Douglas-Peucker tolerance for the copy of Q̃ the chains offset
  double stage_input;   // Douglas-Peucker tolerance for stage 1's result before the inset
};

Budget budget(double d) { return {d / 32.0, d / 2.0, d / 32.0, d / 4.0, d / 4.0}; }

void check_cancel(const CancelHook& cancel) {
  if (cancel && cancel()) throw Cancelled();
}

// One offset stage, with the disk-size limit enforced before Clipper runs. `unit` is the number
// of grid units per input unit (for the message).
IRegion offset_stage(const IRings& rings, double delta, double tol, const DeconstructLimits& limits,
                     double unit, std::size_t& disk_vertices, Spokes spokes = Spokes::kCovered) {
  const double steps = std::ceil(round_join_steps(delta, tol));
  if (steps > static_cast<double>(limits.max_disk_vertices)) {
    throw InvalidInput("fast engine: a disk of radius " + std::to_string(std::fabs(delta) / unit) +
                       " at tolerance " + std::to_string(tol / unit) + " needs " +
                       std::to_string(static_cast<long long>(steps)) +
                       " vertices, over the limit of " + std::to_string(limits.max_disk_vertices) +
                       " (precision too fine for the radius)");
  }
  disk_vertices = std::max(disk_vertices, static_cast<std::size_t>(steps));
  return offset_round(rings, delta, tol, spokes);
}

// Offsets and insets of inputs with more vertices than this go in steps (below).
constexpr std::size_t kStepwiseOffsetVertices = 4096;

// An approximation R of offset(rings, delta) with offset(delta - tol) ⊆ R ⊆ offset(delta), as
// offset_stage gives (delta < 0: the same for the inset), computed in k steps of tol/k each
// when the input is large: Minkowski sums with disks compose (D_a ⊕ D_b = D_{a+b}), so do
// erosions, and each step's approximation loses at most its tolerance: the k losses add up to
// tol, so the bounds are the same. A dense, jagged ring's one-step offset makes Clipper resolve
// the crossings of every offset edge with all the others within 2 delta (1.9 s of 3 s at 200,000
// vertices); small first steps fill the jags, so each step meets few. With the striped union
// (OffsetMode::kStriped) three steps (cumulative radii delta/16, delta/4, delta, tol/3 each: fewer
// arc vertices per step) cost less than the former four (delta/32, delta/8, delta/2, delta at
// tol/4), which OffsetMode::kFormer keeps for the bench's side-by-side figure.
IRegion offset_stepped(const IRings& rings, double delta, double tol,
                       const DeconstructLimits& limits, double unit, std::size_t& disk_vertices,
                       Spokes spokes = Spokes::kCovered) {
  std::size_t n = 0;
  for (const IRing& ring : rings) n += ring.size();
  if (n <= kStepwiseOffsetVertices || std::fabs(delta) <= 4.0 * tol) {
    return offset_stage(rings, delta, tol, limits, unit, disk_vertices, spokes);
  }
  static constexpr double kFormer[] = {1.0 / 32, 1.0 / 8, 1.0 / 2};
  static constexpr double kStriped[] = {1.0 / 16, 1.0 / 4};
  const std::span<const double> fractions =
      offset_mode() == OffsetMode::kFormer ? std::span<const double>(kFormer) : kStriped;
  const double step_tol = tol / static_cast<double>(fractions.size() + 1);
  IRings current = rings;
  double done = 0.0;
  for (const double f : fractions) {
    current = flatten(
        offset_stage(current, delta * f - done, step_tol, limits, unit, disk_vertices, spokes));
    done = delta * f;
  }
  return offset_stage(current, delta - done, step_tol, limits, unit, disk_vertices, spokes);
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

// Vertices of Q that lie outside Q̂', farthest first: exact points of Q for
// verify_no_vertex_witness (slivers thinner than a few grid units have no grid point deep inside
// Q̃ to serve as a witness).
std::vector<const ExactPoint*> vertex_candidates(const PolygonSet& q, const GridFrame& frame,
                                                 const SegmentIndex& q_hat_prime) {
  std::vector<std::pair<double, const ExactPoint*>> scored;
  auto consider = [&](const Ring& ring) {
    for (const ExactPoint& v : ring) {
      const IPt g = frame.round(v);
      if (q_hat_prime.winding(g) > 0) continue;
      scored.push_back({q_hat_prime.distance(to_d(g), 1e18), &v});
    }
  };
  for (const PolygonWithHoles& poly : q.polygons) {
    consider(poly.outer);
    for (const Ring& hole : poly.holes) consider(hole);
  }
  std::sort(scored.begin(), scored.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<const ExactPoint*> out;
  for (std::size_t i = 0; i < scored.size() && out.size() < 6; ++i) out.push_back(scored[i].second);
  return out;
}

// The grid, Q̃ and its index, the solid part of Q̃ (its left-out polygons into `left_out`) and
// Q_s: what a decision builds first.
std::unique_ptr<FastWork> build_work(const PolygonSet& q, const DeconstructParams& params,
                                     std::vector<std::size_t>& left_out, IRings& solid) {
  GridFrame frame(q, params);
  const double eps = frame.units(params.tolerance);
  const double tolerance = budget(frame.units(params.precision)).input;
  GridInput grid = frame.round(q);
  SegmentIndex q_index(grid.rings, eps / 2.0);
  solid = grid.solid_rings(left_out);
  CertifiedInput input = certified_input(solid, tolerance, eps / 2.0);
  return std::unique_ptr<FastWork>(new FastWork{std::move(frame), std::move(grid),
                                                std::move(q_index), std::move(input), tolerance,
                                                std::nullopt});
}

// One decision: the grid, Q̃ and its solid part, then the YES and NO attempts.
class FastDecision {
 public:
  FastDecision(const PolygonSet& q, const DeconstructParams& params, const CancelHook& cancel,
               const DeconstructLimits& limits, DeconstructResult& result)
      : q_(q),
        params_(params),
        cancel_(cancel),
        limits_(limits),
        result_(result),
        work_(build_work(q, params, left_out_, solid_)),
        frame_(work_->frame),
        r_(frame_.units(params.radius)),
        eps_(frame_.units(params.tolerance)),
        unit_(frame_.units(Rational(1))),
        b_(budget(frame_.units(params.precision))),
        grid_(work_->grid),
        q_index_(work_->q_index),
        input_(work_->input),
        sigma_(input_.eta - kInputRounding) {}

  // What the decision built, for the simplifier of the same call (fast_work.hpp).
  std::unique_ptr<FastWork> release_work() { return std::move(work_); }

  // Whether the grid lost part of Q for the certificates: polygons left out of the solid region,
  // a solid region that is not simple, or a ring within the rounding's reach of collapsing.
  [[nodiscard]] bool lost_features() const {
    return !left_out_.empty() || !input_.index || grid_.has_thin_ring();
  }

  // Interior chain (Algorithm 2 with margins) on Q_s: P ⊆ inset(offset(Q_s, eps - 2m - σ),
  // r + 2m), then the certificate of yes_certificate.hpp. Stage 1's result X is first
  // simplified by s = stage_input and inset s deeper: a point whose disk of radius r' + s lies in
  // the simplified X has its r' disk in X (the simplification moves ∂X by at most s, README.md),
  // so the chain's bounds hold with s more loss, and the inset's Clipper pass meets far fewer
  // crossings. When that candidate does not verify (a thin Π̂ the deeper inset loses), X itself
  // is inset as before: every YES the former chain found is still found.
  //
  // Before all that, the same chain runs once with the spokes of narrow reflex corners left out
  // of the raw offset paths (Spokes::kNarrow, raw_offset.hpp): Clipper then meets far fewer
  // crossings (KAZ at r = w/30: the decision 6.5-6.9 -> 5.5-5.8 ms CPU), but the regions may miss
  // slivers along a dropped spoke, so its P is only a candidate like any other. When it does
  // not verify, the exact chain runs as before (its YES are all still found). Only on inputs
  // offset in one step: the stepped offsets of large inputs meet few spokes' crossings (the
  // small first step fills the jags), and on the 200,000-vertex star of scale_bench the
  // candidate did not verify (425 -> 580 ms).
  bool try_yes() {
    if (!input_.index) return false;
    YesCheckInput in = yes_check_input(input_, q_index_, frame_, q_, params_, b_.margin);
    in.memo = &work_->memo.emplace(*input_.index, level_a(in), in.max_sagitta);
    std::size_t n = 0;
    for (const IRing& ring : q_simple()) n += ring.size();
    return (n <= kStepwiseOffsetVertices && yes_chain(in, Spokes::kNarrow)) ||
           yes_chain(in, Spokes::kCovered);
  }

  // Stage 1, then stage 2 on X_s (and, with the exact raw paths, on X).
  bool yes_chain(const YesCheckInput& in, Spokes spokes) {
    const IRegion q_eps =
        offset_stepped(q_simple(), eps_ - 2 * b_.margin - sigma_, b_.arc_tolerance, limits_, unit_,
                       result_.disk_vertices, spokes);
    check_cancel(cancel_);
    return yes_from(flatten(simplify_rings_only(q_eps, b_.stage_input)), b_.stage_input, in,
                    spokes) ||
           (spokes == Spokes::kCovered && yes_from(flatten(q_eps), 0.0, in, spokes));
  }

  // The candidate inset(x, r + 2m + arc + extra), simplified: YES when it verifies.
  bool yes_from(const IRings& x, double extra, const YesCheckInput& in, Spokes spokes) {
    const IRegion pi_hat =
        offset_stepped(x, -(r_ + 2 * b_.margin + b_.arc_tolerance + extra), b_.arc_tolerance,
                       limits_, unit_, result_.disk_vertices, spokes);
    check_cancel(cancel_);
    if (pi_hat.empty()) return false;
    // Ring-wise simplification is usually still a valid region; otherwise let Clipper union it.
    // The candidate's index serves both the test and the check (built once).
    std::optional<YesCandidate> c;
    c.emplace(in, simplify_rings_only(pi_hat, b_.simplify));
    if (!c->certifiable) c.emplace(in, simplify(pi_hat, b_.simplify));
    if (!verify_yes(in, *c, cancel_)) return false;
    result_.answer = Answer::kYes;
    result_.solution = to_polygon_set(frame_, c->p);
    result_.hausdorff_bound = params_.tolerance;
    return true;
  }

  // Exterior chain (Algorithm 3 with margins): Q̂' ⊇ offset(Π, r + eps) with room to spare; NO
  // witnesses are proposed outside it and verified (no_certificate.hpp).
  bool try_no() {
    const double eps_out = eps_ + 2 * b_.margin + sigma_ + b_.arc_tolerance;
    const IRegion q_eps_out = offset_stepped(q_simple(), eps_out, b_.arc_tolerance, limits_, unit_,
                                             result_.disk_vertices);
    check_cancel(cancel_);
    const IRegion pi_out = offset_stepped(flatten(q_eps_out), -(r_ - 2 * b_.margin),
                                          b_.arc_tolerance, limits_, unit_, result_.disk_vertices);
    check_cancel(cancel_);
    const IRegion q_prime_out =
        offset_stepped(flatten(pi_out), r_ + eps_ + 2 * b_.margin + b_.arc_tolerance,
                       b_.arc_tolerance, limits_, unit_, result_.disk_vertices);
    check_cancel(cancel_);
    const IRegion diff = difference(grid_.rings, flatten(q_prime_out));

    const SegmentIndex outer_index(flatten(q_eps_out), r_ / 2.0);
    const SegmentIndex q_prime_index(flatten(q_prime_out), r_ / 2.0);
    const NoCheckInput no{&q_index_,
                          &outer_index,
                          frame_.bounds(params_.radius),
                          frame_.bounds(params_.tolerance),
                          b_.margin / 2.0,
                          b_.margin / 4.0};
    for (const IPt& w : witness_candidates(diff, q_index_, q_prime_index)) {
      if (verify_no_witness(no, w, cancel_)) {
        result_.answer = Answer::kNo;
        result_.no_witness = frame_.exact(w); // a grid point of Q̃ deep enough to be in Q
        return true;
      }
    }
    for (const ExactPoint* v : vertex_candidates(q_, frame_, q_prime_index)) {
      if (verify_no_vertex_witness(no, frame_.round(*v), cancel_)) {
        result_.answer = Answer::kNo;
        result_.no_witness = *v; // a vertex of Q: in Q, which is closed
        return true;
      }
    }
    return false;
  }

 private:
  const PolygonSet& q_;
  const DeconstructParams& params_;
  const CancelHook& cancel_;
  const DeconstructLimits& limits_;
  DeconstructResult& result_;
  std::vector<std::size_t> left_out_;
  IRings solid_;
  std::unique_ptr<FastWork> work_;
  const GridFrame& frame_;
  const double r_, eps_, unit_;
  const Budget b_;
  const GridInput& grid_;
  const SegmentIndex& q_index_;
  const CertifiedInput& input_;
  const double sigma_;

  // Q_s, the region the chains offset; without a certifiable Q_s the chains still run on the
  // solid rings (for NO), but YES cannot be certified.
  [[nodiscard]] const IRings& q_simple() const {
    return input_.index ? input_.index->rings() : solid_;
  }
};

} // namespace

DeconstructResult decide_fast(const PolygonSet& q_any, const DeconstructParams& params,
                              const CancelHook& cancel, const DeconstructLimits& limits,
                              bool* lost_features, std::unique_ptr<FastWork>* keep, bool oriented) {
  const auto start = std::chrono::steady_clock::now();
  DeconstructResult result;
  result.engine = EngineKind::kFast;
  result.params = params;
  // The grid keeps each ring's vertex order: orient Q exactly first (deconstruct() already has).
  PolygonSet fixed;
  const bool needs_fix = !oriented && !has_normalized_orientation(q_any);
  if (needs_fix) {
    fixed = q_any;
    normalize_orientation(fixed);
  }
  FastDecision decision(needs_fix ? fixed : q_any, params, cancel, limits, result);
  check_cancel(cancel);
  if (!decision.try_yes()) {
    check_cancel(cancel);
    decision.try_no();
  }
  // Only an UNDECIDED answer needs to know (the thin-ring scan is not free).
  if (lost_features != nullptr) {
    *lost_features = result.answer == Answer::kUndecided && decision.lost_features();
  }
  if (keep != nullptr) *keep = decision.release_work();
  result.elapsed = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::steady_clock::now() - start);
  return result;
}

} // namespace penshape::detail
