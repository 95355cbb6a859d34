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

} // namespace penshape
