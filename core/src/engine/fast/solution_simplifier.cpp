// Fewer vertices for a fast-engine YES solution (issue: simple-looking solutions). Two moves,
// each candidate certified by the same exact-grid YES check as decide_fast (yes_certificate):
//   - indented caps (Theorem 5): a run of right turns is an arc of Π̂'s boundary bulging into
//     the region; replacing it by the two tangent lines' intersection removes the linear cap,
//     which the (r + ε)-offset does not need (the cap lies in the disks around the arc's ends);
//   - coarser Douglas-Peucker on what remains;
//   - then single vertices of the best candidate, each drop kept only if the result verifies
//     (Douglas-Peucker's tolerance is symmetric: one that cuts nowhere outside Π is too fine
//     elsewhere; issue 26: KAZ at r = w/30 went from 119 to 25 vertices).
// Nothing here is trusted: a candidate that does not verify is dropped.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "clipper_stage.hpp"
#include "douglas_peucker.hpp"
#include "engine/engines.hpp"
#include "fast_work.hpp"
#include "grid_frame.hpp"
#include "level_set_check.hpp"
#include "region_convert.hpp"
#include "segment_index.hpp"
#include "yes_certificate.hpp"

namespace penshape::detail {
namespace {

using namespace penshape::fast;

// Largest total turn of one cap: Theorem 5 splits arcs into pieces of at most a quarter circle.
constexpr double kMaxCapTurn = std::numbers::pi / 2 * 0.95;
// Work cap of the whole checks of candidates and of the single-vertex drops: checks ×
// (|Q̃| + |P|) vertices each, so a large input pays a few checks rather than two per vertex of P
// (a cost bound, about 2^20 / 2000 checks on KAZ, 5 on 200,000 vertices).
constexpr std::size_t kDropWork = std::size_t{1} << 20;
// Q_s for the checks here is simplified at d / kInputFraction (d = delta in grid units), or at
// d / kFewChecksFraction, the decision's own, when the work cap leaves fewer than kFewChecks
// whole checks (Q̃ over 2^15 vertices): every check walks all of Q_s's level set, so there the
// finer copy's room buys little and costs a walk over nearly all of Q (issue 26: 1.3 s of the
// CLI's 200,000-vertex call, 0.35 s with the coarser copy, the same |P|).
constexpr double kInputFraction = 16.0;
constexpr double kFewChecksFraction = 4.0;
constexpr std::size_t kFewChecks = 32;

double turn_angle(IPt a, IPt b, IPt c) { // signed, positive for a left turn
  const double ux = static_cast<double>(b.x - a.x);
  const double uy = static_cast<double>(b.y - a.y);
  const double vx = static_cast<double>(c.x - b.x);
  const double vy = static_cast<double>(c.y - b.y);
  return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

// Intersection of the lines through (a, b) and (c, d), rounded to the grid; nullopt when they
// are (nearly) parallel.
std::optional<IPt> line_intersection(IPt a, IPt b, IPt c, IPt d) {
  const double rx = static_cast<double>(b.x - a.x);
  const double ry = static_cast<double>(b.y - a.y);
  const double sx = static_cast<double>(d.x - c.x);
  const double sy = static_cast<double>(d.y - c.y);
  const double den = rx * sy - ry * sx;
  if (std::abs(den) < 1e-9 * std::hypot(rx, ry) * std::hypot(sx, sy)) return std::nullopt;
  const double t =
      (static_cast<double>(c.x - a.x) * sy - static_cast<double>(c.y - a.y) * sx) / den;
  return IPt{std::llround(static_cast<double>(a.x) + t * rx),
             std::llround(static_cast<double>(a.y) + t * ry)};
}

// Replaces each run of right turns (an indented arc; the region is on the left of every ring)
// by the intersection of the edges entering and leaving it, splitting runs that turn more than
// a quarter circle.
IRing remove_caps(const IRing& ring) {
  const std::size_t n = ring.size();
  if (n < 4) return ring;
  auto at = [&](std::size_t i) { return ring[i % n]; };
  // Start after a vertex that is not a right turn, so no run wraps around the start.
  std::size_t start = n;
  for (std::size_t i = 0; i < n; ++i) {
    if (orientation(at(i + n - 1), at(i), at(i + 1)) >= 0) {
      start = i;
      break;
    }
  }
  if (start == n) return ring; // all right turns: a clockwise convex ring, nothing to cut
  IRing out;
  std::size_t i = start + 1;
  const std::size_t end = start + 1 + n;
  out.push_back(at(start));
  while (i < end) {
    if (orientation(at(i - 1), at(i), at(i + 1)) >= 0) {
      out.push_back(at(i));
      ++i;
      continue;
    }
    // A run of right turns from i; grow it while the total turn stays under a quarter circle.
    std::size_t j = i;
    double turned = -turn_angle(at(i - 1), at(i), at(i + 1));
    while (j + 1 < end && orientation(at(j), at(j + 1), at(j + 2)) < 0) {
      const double next = -turn_angle(at(j), at(j + 1), at(j + 2));
      if (turned + next > kMaxCapTurn) break;
      turned += next;
      ++j;
    }
    if (j > i) {
      if (auto x = line_intersection(at(i - 1), at(i), at(j), at(j + 1))) {
        out.push_back(*x);
        i = j + 1;
        continue;
      }
    }
    out.push_back(at(i));
    ++i;
  }
  if (!out.empty() && out.front() == out.back()) out.pop_back();
  return out;
}

std::size_t vertex_count(const IRegion& region) {
  std::size_t n = 0;
  for (const auto& p : region) {
    n += p.outer.size();
    for (const auto& h : p.holes) n += h.size();
  }
  return n;
}

// Vertex i of ring r of polygon p (r = 0: the outer ring).
IRing& ring_at(IRegion& region, std::size_t p, std::size_t r) {
  return r == 0 ? region[p].outer : region[p].holes[r - 1];
}

// Each ring of `region` (which verify_yes accepted) in turn: a vertex is dropped when the region
// without it still verifies (the same YES check, walked only near the dropped vertex's triangle,
// which is all that changes: verify_yes_after_drop), else kept. `budget` caps the checks.
bool drop_vertices(const YesCheckInput& in, IRegion& region, std::size_t& budget,
                   const CancelHook& cancel) {
  bool dropped = false;
  for (std::size_t p = 0; p < region.size(); ++p) {
    for (std::size_t r = 0; r <= region[p].holes.size(); ++r) {
      std::size_t i = 0;
      while (i < ring_at(region, p, r).size() && ring_at(region, p, r).size() > 3) {
        if (budget == 0) return dropped;
        if (cancel && cancel()) throw Cancelled();
        --budget;
        IRegion candidate = region;
        IRing& ring = ring_at(candidate, p, r);
        const std::size_t n = ring.size();
        const IPt before = ring[(i + n - 1) % n], gone = ring[i], after = ring[(i + 1) % n];
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        // `region` verified (before the pass, or as a candidate): only T's surroundings change.
        if (verify_yes_after_drop(in, candidate, before, gone, after, cancel)) {
          region = std::move(candidate); // the next vertex is now at i
          dropped = true;
        } else {
          ++i;
        }
      }
    }
  }
  return dropped;
}

// The fewest-vertex candidate that verifies: indented caps removed, or not, then Douglas-Peucker
// coarsest first (the first that verifies and saves vertices wins per family); at most `checks`
// verifications. Nothing when none verifies.
std::optional<IRegion> coarsest_verified(const YesCheckInput& in, const IRegion& raw, double eps,
                                         double d, std::size_t& checks, const CancelHook& cancel) {
  IRings capped;
  for (const IRing& ring : flatten(raw)) capped.push_back(remove_caps(ring));
  const IRings plain = flatten(raw);
  std::optional<IRegion> best;
  std::size_t best_count = vertex_count(raw);
  for (const IRings* rings_ptr : std::array<const IRings*, 2>{&capped, &plain}) {
    for (double tol = eps / 2.0; tol >= d / 16.0 && checks > 0; tol /= 2.0) {
      if (cancel && cancel()) throw Cancelled();
      const IRegion candidate = simplify(*rings_ptr, tol);
      const std::size_t count = vertex_count(candidate);
      if (candidate.empty() || count >= best_count) continue;
      --checks;
      if (verify_yes(in, candidate, cancel)) {
        best = candidate;
        best_count = count;
        break;
      }
    }
  }
  return best;
}

// The simplifier's own grid, Q̃ and Q_s, each taken from the decision's work when it has one
// (the decision's Q_s only when it is the one wanted here: on large inputs, see kFewChecks).
class CheckSetup {
 public:
  CheckSetup(const PolygonSet& q, const DeconstructParams& params, FastWork* work) {
    if (work == nullptr) own_frame_.emplace(q, params);
    frame_ = work != nullptr ? &work->frame : &*own_frame_;
    if (work == nullptr) own_grid_.emplace(frame_->round(q));
    grid_ = work != nullptr ? &work->grid : &*own_grid_;
    for (const IRing& ring : grid_->rings) q_count_ += ring.size();
    const double eps = frame_->units(params.tolerance);
    const double d = frame_->units(params.precision);
    // Q_s for the checks is simplified at d / kInputFraction, or at the decision's own d / 4
    // when the work cap leaves fewer than kFewChecks whole checks (see kFewChecksFraction).
    const double tolerance =
        d / (q_count_ > kDropWork / kFewChecks ? kFewChecksFraction : kInputFraction);
    if (work != nullptr && work->input_tolerance == tolerance) {
      input_ = &work->input;
      memo_ = work->memo ? &*work->memo : nullptr;
    } else {
      std::vector<std::size_t> left_out;
      own_input_ = certified_input(grid_->solid_rings(left_out), tolerance, eps / 2.0);
      input_ = &own_input_;
    }
    if (work == nullptr) own_index_.emplace(grid_->rings, eps / 2.0);
    q_index_ = work != nullptr ? &work->q_index : &*own_index_;
  }

  [[nodiscard]] const GridFrame& frame() const { return *frame_; }
  [[nodiscard]] std::size_t q_count() const { return q_count_; }

  // The YES check's input, with a memo of the (A1) walk's deep pieces (the decision's when its
  // Q_s is used, so pieces it proved deep are not tested again); nothing without a Q_s.
  std::optional<YesCheckInput> check_input(const PolygonSet& q, const DeconstructParams& params) {
    if (!input_->index) return std::nullopt;
    YesCheckInput in = yes_check_input(*input_, *q_index_, *frame_, q, params,
                                       frame_->units(params.precision) / 32.0);
    if (memo_ == nullptr || !memo_->serves(in.q, level_a(in), in.max_sagitta)) {
      memo_ = &own_memo_.emplace(*input_->index, level_a(in), in.max_sagitta);
    }
    in.memo = memo_;
    return in;
  }

 private:
  std::optional<GridFrame> own_frame_;
  std::optional<GridInput> own_grid_;
  std::optional<SegmentIndex> own_index_;
  CertifiedInput own_input_;
  std::optional<LevelSetMemo> own_memo_;
  const GridFrame* frame_ = nullptr;
  const GridInput* grid_ = nullptr;
  const SegmentIndex* q_index_ = nullptr;
  const CertifiedInput* input_ = nullptr;
  LevelSetMemo* memo_ = nullptr;
  std::size_t q_count_ = 0;
};

} // namespace

std::optional<PolygonSet> simplify_fast_solution(const PolygonSet& q_any,
                                                 const DeconstructParams& params,
                                                 const PolygonSet& solution,
                                                 const CancelHook& cancel, FastWork* work) {
  // The grid keeps each ring's vertex order: orient Q exactly first (copying Q only when it
  // needs it: deconstruct() hands the engines oriented input, and a copy of 200,000 exact
  // vertices costs more than the check). The decision's work was built from oriented Q.
  std::optional<PolygonSet> reoriented;
  if (work == nullptr && !has_normalized_orientation(q_any)) {
    normalize_orientation(reoriented.emplace(q_any));
  }
  const PolygonSet& q = reoriented ? *reoriented : q_any;
  CheckSetup setup(q, params, work);
  // The certificate's region A is a Douglas-Peucker copy Q_s of the solid part of Q̃ (finer
  // than the decision's on small inputs): the drop pass checks up to two candidates per vertex
  // of P, and each walks A's level set, so A's size is what they cost (the solid part itself
  // made KAZ's pass take about 1 s and a 200,000-vertex input's 20 s). B is all of Q̃.
  const std::optional<YesCheckInput> in = setup.check_input(q, params);
  if (!in) return std::nullopt;
  const double eps = setup.frame().units(params.tolerance);
  const double d = setup.frame().units(params.precision);

  const IRegion raw = to_grid(setup.frame(), solution);
  // Whole checks of Douglas-Peucker candidates, within the same work cap as the drops below.
  std::size_t checks = std::max<std::size_t>(1, kDropWork / (setup.q_count() + vertex_count(raw)));
  std::optional<IRegion> best = coarsest_verified(*in, raw, eps, d, checks, cancel);
  if (!best) return std::nullopt;
  // Then single vertices: at most two checks per vertex, within the work cap.
  std::size_t budget =
      std::min(2 * vertex_count(*best), kDropWork / (setup.q_count() + vertex_count(*best)));
  while (budget > 0 && drop_vertices(*in, *best, budget, cancel)) {
  }
  return to_polygon_set(setup.frame(), *best);
}

} // namespace penshape::detail
