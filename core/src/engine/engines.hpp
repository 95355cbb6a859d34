#pragma once
// The two deconstruction engines behind deconstruct() (deconstruct/deconstruct.cpp). Internal:
// callers use penshape/core/deconstruct.hpp. Both receive validated input with r > eps (the
// r <= eps case is answered before dispatch) and must give certified YES/NO answers; they may
// differ only in speed and in which undecided cases they can settle.
#include <memory>
#include <optional>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/validated_region.hpp"

namespace penshape::detail {

// What a fast decision built (grid, Q̃, Q_s, the YES walk's memo), for the simplifier of the
// same Q and parameters (engine/fast/fast_work.hpp).
struct FastWork;

// The paper's APPROXDECIDE literally: CGAL exact Minkowski sums and Boolean set operations on
// D̄_{a,b} disk approximations. The baseline and the test oracle.
DeconstructResult decide_reference(const PolygonSet& q, const DeconstructParams& params,
                                   const CancelHook& cancel, const DeconstructLimits& limits);

// The default engine: the same certified answers, much faster. `lost_features` (optional) is set
// when the answer is UNDECIDED and the integer grid could not represent all of Q for the
// certificates (a feature thinner than a grid unit: a sliver ring, a non-simple rounding, a ring
// the rounding nearly collapses): that UNDECIDED may be one the reference engine settles, and
// deconstruct() asks it. `keep` (optional) receives what the decision built. `oriented`: the
// caller guarantees outer rings counterclockwise and holes clockwise (deconstruct() has made them
// so), which the engine otherwise checks first.
DeconstructResult decide_fast(const PolygonSet& q, const DeconstructParams& params,
                              const CancelHook& cancel, const DeconstructLimits& limits,
                              bool* lost_features = nullptr,
                              std::unique_ptr<FastWork>* keep = nullptr, bool oriented = false);

// Fewer vertices for a YES solution of decide_fast (same q and params): indented caps removed
// (Theorem 5) and coarser simplification, each candidate certified by the fast engine's
// exact-grid YES check. nullopt when no candidate verifies and saves vertices. `work`, when
// given, is what decide_fast kept for this very Q and params (the caller guarantees it).
std::optional<PolygonSet> simplify_fast_solution(const PolygonSet& q,
                                                 const DeconstructParams& params,
                                                 const PolygonSet& solution,
                                                 const CancelHook& cancel,
                                                 FastWork* work = nullptr);

// deconstruct(q, params) that also hands over the fast engine's work (`keep`, reset when the
// fast engine did not answer) for simplify_with_work on the same q and params.
DeconstructResult deconstruct_keeping(const ValidatedRegion& q, const DeconstructParams& params,
                                      const CancelHook& cancel, const DeconstructLimits& limits,
                                      std::unique_ptr<FastWork>& keep);

} // namespace penshape::detail
