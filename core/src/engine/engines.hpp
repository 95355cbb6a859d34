#pragma once
// The two deconstruction engines behind deconstruct() (core/src/deconstruct.cpp). Internal:
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
// when its integer grid could not represent all of Q for the YES certificate (a feature thinner
// than a grid unit, so a sliver ring or a non-simple rounding): its UNDECIDED may then be one
// the reference engine settles, and deconstruct() asks it.
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
