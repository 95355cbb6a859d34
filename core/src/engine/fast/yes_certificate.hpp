#pragma once
// Exact-grid verification of a YES candidate P against an integer region Q̃ with a proven
// bound η >= H(Q, Q̃) (README.md, "Why YES is certified"). It proves in grid units
//   (A) offset(P, r) ⊆ {d(·, Q̃) <= eps - η} ⊆ offset(Q, eps), i.e. P ⊆ Π, and
//   (B) Q ⊆ offset(P, r + eps),
// so H(offset(P, r), Q) <= eps (Proposition 3). False means "not verified", never "wrong".
#include <vector>

#include "certified.hpp"
#include "clipper_stage.hpp"
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
};

bool verify_yes(const YesCheckInput& in, const IRegion& p, const CancelHook& cancel);

} // namespace penshape::fast
