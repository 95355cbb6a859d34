#pragma once
// Verification of a NO witness (README.md, "Why NO is certified"): a grid point q of Q such that
// every point y of the disk D_{r+eps}(q) has, within distance r, a point z with d(z, Q) > eps.
// Then no y of that disk lies in Π = inset(offset(Q, eps), r), so q ∉ offset(Π, r + eps) and
// DECIDE(Q, r, eps) answers NO. The disk is covered by a quadtree; each cell gets one witness z,
// taken from the boundary of the exterior approximation of offset(Q, eps) (outside it, pushed
// out a little) or the cell centre itself, and every witness and every dropped cell is checked
// with the certified predicates of certified.hpp.
#include <cstddef>

#include "certified.hpp"
#include "penshape/core/deconstruct.hpp"
#include "segment_index.hpp"

namespace penshape::fast {

struct NoCheckInput {
  const SegmentIndex* q = nullptr;            // Q̃
  const SegmentIndex* outer_offset = nullptr; // boundary of a region ⊇ offset(Q̃, eps + margin)
  Bounds radius;                              // r, grid units (exact value enclosed)
  Bounds tolerance;                           // eps, grid units (exact value enclosed)
  double push = 1.0;                          // how far witnesses are pushed off that boundary
  double min_cell = 1.0;                      // smallest cell radius before giving up
  std::size_t max_cells = 200'000;
};

// Whether q (a grid point) is a verified NO witness.
bool verify_no_witness(const NoCheckInput& in, IPt q, const CancelHook& cancel);

// Whether an exact vertex v of Q (a point of Q, which is closed, whatever Q̃ looks like near it:
// a sliver thinner than a grid unit has no grid point inside) is a verified NO witness, given
// its grid point ṽ = `rounded`: the disk of radius r + eps + η0 around ṽ, which contains
// D_{r+eps}(v), is covered as above.
bool verify_no_vertex_witness(const NoCheckInput& in, IPt rounded, const CancelHook& cancel);

} // namespace penshape::fast
