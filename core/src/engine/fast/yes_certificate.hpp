#pragma once
// Exact-grid verification of a YES candidate P against an integer region Q̃ with a proven
// bound η >= H(Q, Q̃) (README.md, "Why YES is certified"). It proves in grid units
//   (A) offset(P, r) ⊆ {d(·, Q̃) <= eps - η} ⊆ offset(Q, eps), i.e. P ⊆ Π, and
//   (B) Q ⊆ offset(P, r + eps),
// so H(offset(P, r), Q) <= eps (Proposition 3). False means "not verified", never "wrong".
#include <optional>
#include <vector>

#include "certified.hpp"
#include "clipper_stage.hpp"
#include "grid_frame.hpp"
#include "level_set_check.hpp"
#include "penshape/core/deconstruct.hpp"
#include "segment_index.hpp"

namespace penshape::fast {

struct YesCheckInput {
  const SegmentIndex* q = nullptr;       // Q̃ or a simplification (simple rings, checked)
  double eta = 0.0;                      // proven upper bound on H(Q, that region), grid units
  const SegmentIndex* q_grid = nullptr;  // Q̃ itself: H(Q, Q̃) <= kInputRounding
  std::vector<IPt> q_component_vertices; // one grid vertex per polygon of Q (its outer ring)
  Bounds radius;                         // r, grid units (exact value enclosed)
  Bounds tolerance;                      // eps, grid units (exact value enclosed)
  double max_sagitta = 1.0;              // chord error when walking arcs
  // Shared by the (A1) walks of every check with this input (A = q at one level): see
  // LevelSetMemo. Optional; a caller checking many candidates sets it.
  LevelSetMemo* memo = nullptr;
};

// The level of (A1)'s walk: eps - η rounded down (then taken as exact).
inline double level_a(const YesCheckInput& in) { return sub_down(in.tolerance.lo, in.eta); }

bool verify_yes(const YesCheckInput& in, const IRegion& p, const CancelHook& cancel);

// A candidate P with the index the check queries (cell r / 2) and whether P is certifiable
// (is_certifiable_region): built once, so that a caller who must know whether P is certifiable
// before checking it (the decision, which unions P with Clipper when it is not) does not build
// and test the same index twice. The certifiable test is exact and does not depend on the cell.
struct YesCandidate {
  YesCandidate(const YesCheckInput& in, IRegion region);
  IRegion p;
  SegmentIndex index;
  bool certifiable;
};

// verify_yes(in, c.p): the same check on the candidate's index.
bool verify_yes(const YesCheckInput& in, const YesCandidate& c, const CancelHook& cancel);

// verify_yes for P' = a region P that verify_yes (or this) accepted with the same `in`, with
// one vertex v dropped from a ring (a and b its neighbours there, T the triangle a v b). P' is
// checked certifiable and (A2), (B2) in full; the walks of (A1) and (B1) only near T, since
// ∂P' ⊆ ∂P ∪ T and P, P' differ only inside T:
//   (A1) a point z of {d(·, Q_s) = L_A} with d(z, T) > r is outside P ∪ T ⊇ P' and has
//        d(z, ∂P') >= min(d(z, ∂P), d(z, T)) > r, both by P's check;
//   (B1) a point z with d(z, T) > L_B has d(z, P') < L_B iff d(z, P) < L_B (a point of either
//        within L_B of z is not in T, so it is in both), and likewise = L_B: there the level
//        set of P' is that of P, which P's check kept outside Q.
// So only the pieces within r (A1) or L_B (B1) of T's bounding box are walked.
bool verify_yes_after_drop(const YesCheckInput& in, const IRegion& p, IPt a, IPt v, IPt b,
                           const CancelHook& cancel);

// The certificate's region A = Q_s: a Douglas-Peucker copy of the grid rings (at `tolerance`,
// or finer when that crosses itself) with a checked distance, H(Q, Q_s) <= eta = 3/4 + the
// tolerance used, simple and consistently nested; else the grid rings themselves (eta = 3/4);
// no index when not even they are (then YES cannot be certified: a finer precision gives a
// finer grid). Fewer edges make every level-set walk over A cheaper.
struct CertifiedInput {
  std::optional<SegmentIndex> index;
  double eta = kInputRounding;
};
CertifiedInput certified_input(const IRings& q_grid, double tolerance, double cell);

// The YES check for Q in `frame` with `params`: A = the certified Q_s `a` (its index set),
// B = Q̃ (`q_grid`), one rounded outer vertex per polygon of Q, arcs walked at `max_sagitta`.
YesCheckInput yes_check_input(const CertifiedInput& a, const SegmentIndex& q_grid,
                              const GridFrame& frame, const PolygonSet& q,
                              const DeconstructParams& params, double max_sagitta);

} // namespace penshape::fast
