#pragma once
// The linear-time path for convex inputs (deconstructing-approximate-offsets, Section 5):
// CONVEXDECIDE. For convex Q, Π = inset(offset(Q, ε), r) is Q's edge half-planes shifted inward
// by r - ε (Lemma 22), and Q is ε-close to offset(Π, r) iff every disk D_{r+ε}(q_i) around a
// vertex of Q meets Π (Lemma 23).
//
// Shifting a line by a distance needs |n| = sqrt(a² + b²); we bracket it by rationals
// L <= |n| <= U, giving Π̂_int ⊆ Π ⊆ Π̂_ext with exact rational vertices:
//   YES  every vertex disk meets Π̂_int   (P = Π̂_int ⊆ Π and, by convexity,
//        Q ⊆ offset(P, r + ε): Proposition 3);
//   NO   some vertex disk misses Π̂_ext (shifted by r - ε - δ/2 ⊇ Π), or Π̂_ext has no
//        interior (then Π, an inset of it, is empty);
//   UNDECIDED otherwise (only when ε is within the bracket's width of ε̂, far below δ).
#include "penshape/core/deconstruct.hpp"

namespace penshape {

// True when q is one polygon without holes whose outer ring turns left (or goes straight) at
// every vertex: a convex region.
bool is_convex_region(const PolygonSet& q);

// CONVEXDECIDE on a validated convex q with r > ε. Linear in the vertex count (plus the
// rational arithmetic's growth). Throws InvalidInput when q is not convex.
DeconstructResult convex_decide(const PolygonSet& q, const DeconstructParams& params,
                                const CancelHook& cancel = {});

// CONVEXDECIDE on a simplified copy Q_s of q (a subsequence of its vertices, so convex, with
// every dropped vertex within σ = δ/4 of its chord, checked exactly: H(Q, Q_s) <= σ): YES at
// ε - σ for Q_s is YES at ε for Q, NO at ε + σ is NO at ε (Hausdorff triangle inequality).
// What neither settles goes to convex_decide on q itself. Smooth inputs (a pen's round ink)
// lose most of their vertices, so this is what deconstruct() runs for convex input.
DeconstructResult convex_decide_simplified(const PolygonSet& q, const DeconstructParams& params,
                                           const CancelHook& cancel = {});

} // namespace penshape

namespace penshape {

// The greedy solution P^s of Section 5 (Theorems 27-30): starting at a point s on ∂Π̂, jump to
// the horizon (the farthest boundary point whose chord still meets every eyelet
// κ_i = D_{r+ε}(q_i) ∩ Π̂ with its spot in between) until the chord back to s is good. At most
// OPT + 1 vertices on non-degenerate inputs; may be a segment or a single point.
//
// Horizons are found in floating point; the returned polygon is then checked exactly (vertices on
// ∂Π̂ with rational coordinates, every vertex disk of Q meets P, so Q ⊆ offset(P, r + ε) and
// P ⊆ Π̂ ⊆ Π by convexity). When the check fails, the result falls back to Π̂ itself, so
// the certificate always holds. `pi_hat` must be a YES solution of convex_decide for q.
struct GreedyResult {
  PolygonSet solution; // the ring may have 1, 2 or more vertices
  std::size_t vertices = 0;
  bool fell_back = false; // the exact check failed and Π̂ was returned
};
GreedyResult convex_greedy_solution(const PolygonSet& q, const PolygonSet& pi_hat,
                                    const Rational& reach, const CancelHook& cancel = {});

} // namespace penshape
