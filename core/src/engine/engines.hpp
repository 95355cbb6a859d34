#pragma once
// The two deconstruction engines behind deconstruct() (deconstruct/deconstruct.cpp). Internal:
// callers use penshape/core/deconstruct.hpp. Both receive validated input with r > eps (the
// r <= eps case is answered before dispatch) and must give certified YES/NO answers; they may
// differ only in speed and in which undecided cases they can settle.
#include <optional>

#include "penshape/core/deconstruct.hpp"

namespace penshape::detail {

// The paper's APPROXDECIDE literally: CGAL exact Minkowski sums and Boolean set operations on
// D̄_{a,b} disk approximations. The baseline and the test oracle.
DeconstructResult decide_reference(const PolygonSet& q, const DeconstructParams& params,
                                   const CancelHook& cancel, const DeconstructLimits& limits);

// The default engine: the same certified answers, much faster. `lost_features` (optional) is set
// when the answer is UNDECIDED and the integer grid could not represent all of Q for the
// certificates (a feature thinner than a grid unit: a sliver ring, a non-simple rounding, a ring
// the rounding nearly collapses): that UNDECIDED may be one the reference engine settles, and
// deconstruct() asks it.
DeconstructResult decide_fast(const PolygonSet& q, const DeconstructParams& params,
                              const CancelHook& cancel, const DeconstructLimits& limits,
                              bool* lost_features = nullptr);

// Fewer vertices for a YES solution of decide_fast (same q and params): indented caps removed
// (Theorem 5) and coarser simplification, each candidate certified by the fast engine's
// exact-grid YES check. nullopt when no candidate verifies and saves vertices.
std::optional<PolygonSet> simplify_fast_solution(const PolygonSet& q,
                                                 const DeconstructParams& params,
                                                 const PolygonSet& solution,
                                                 const CancelHook& cancel);

} // namespace penshape::detail
