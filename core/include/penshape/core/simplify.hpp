#pragma once
// Simple-looking solutions for any Q (the paper leaves this open, Section 6 (iv)).
//
// The idea: decide at the smaller tolerance ε' = ε - τ, getting Π̂' with Q ⊆ offset(Π̂', r + ε')
// and Π̂' ⊆ Π_{ε'} = inset(offset(Q, ε'), r). Then ANY closed set P within Hausdorff distance τ of
// Π̂' is a certified solution at ε:
//   P ⊆ offset(Π̂', τ) ⊆ offset(Π_{ε'}, τ) ⊆ inset(offset(offset(Q, ε'), τ), r) = Π_ε, and
//   Q ⊆ offset(Π̂', r + ε') ⊆ offset(offset(P, τ), r + ε') = offset(P, r + ε).
// So simplification is τ-simplification of Π̂' with room to spare: each ring of Π̂' is replaced by
// a chain of chords that stays within τ of the ring it replaces (checked exactly), the rings stay
// simple, disjoint and nested as before (checked exactly), and a region that is within τ of an
// open polyline collapses to it (a segment for a straight wide stroke). Degenerate solutions are
// rings of zero area: [a, b] is the segment ab, [a, p, b, p] the polyline a-p-b.
#include <cstddef>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/validated_region.hpp"

namespace penshape {

struct SimplifyOptions {
  // τ as a fraction of ε; when the decider is not YES at ε - τ, τ halves (at most `attempts`
  // times) before giving up and returning the raw solution.
  Rational tau_fraction = Rational(3, 4);
  std::size_t attempts = 4;
  bool allow_degenerate = true; // segments and open polylines
};

struct SimplifyResult {
  // The certified solution at params.tolerance (= ε): simplified when `simplified`, else the raw
  // solution given.
  DeconstructResult result;
  bool simplified = false;
  Rational tau;                      // the τ used (0 when not simplified)
  std::size_t raw_vertices = 0;      // |Π̂| of the raw solution at ε
  std::size_t solution_vertices = 0; // distinct vertices of the returned solution
  std::size_t decider_calls = 0;
};

// `raw` must be a YES of deconstruct(q, params). Throws what deconstruct throws (Cancelled,
// InvalidInput).
SimplifyResult simplify_solution(const PolygonSet& q, const DeconstructResult& raw,
                                 const CancelHook& cancel = {},
                                 const DeconstructLimits& limits = {},
                                 const SimplifyOptions& options = {});

// deconstruct(q, params), then simplify_solution of a YES: the same results, but the simplifier
// reuses what the fast engine built for the decision (the grid, Q̃, the certified Q_s and the
// YES walk's deep pieces) instead of building it again. Not YES: the decision as it is
// (`simplified` false, no vertex counts).
SimplifyResult deconstruct_simplified(const ValidatedRegion& q, const DeconstructParams& params,
                                      const CancelHook& cancel = {},
                                      const DeconstructLimits& limits = {},
                                      const SimplifyOptions& options = {});

// Building blocks, exposed for tests.
// Vertices of `ring` (a closed ring) to keep so that every dropped vertex is within distance τ
// of the chord that replaces it (exact check); indices in order.
std::vector<std::size_t> simplify_ring_indices(const Ring& ring, const Rational& tau);
// True when every ring is simple, no two rings' edges meet, and holes lie inside their outers
// (exact).
bool is_valid_region(const PolygonSet& set);
// Distinct vertices, counting a degenerate ring's back-and-forth once.
std::size_t distinct_vertex_count(const PolygonSet& set);

} // namespace penshape
