#pragma once
// Parameter searches over the certified decider (deconstructing-approximate-offsets, Section 4):
//   - search_tolerance: for Q and r, an interval of width <= Δ holding ε̂(r) (APPROXSEARCHEPS),
//     then a certified solution at ε̃ <= ε̂ + Δ;
//   - search_radius:    for Q and ε, the radii with a solution form [0, r*]; bounds on r*;
//   - suggest_radius:   local maxima of J(r) = r / ε̂(r) over a sampled range (the Flower
//     example), each with its solution.
// Every function calls a Decider; the default one is penshape::deconstruct(). The searches rely
// on the decider's guarantee (Theorems 11, 13): UNDECIDED at (ε, δ) implies |ε - ε̂| <= 2δ.
// A decider's YES and NO are proofs; its UNDECIDED is only a promise. search_tolerance notices
// a broken promise (the fast engine can stay UNDECIDED far from ε̂ on features narrower than δ)
// and then re-searches with a fallback decider, or reports the interval its proofs give.
#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "penshape/core/deconstruct.hpp"

namespace penshape {

// APPROXDECIDE at (r, ε, δ) for a fixed Q.
using Decider = std::function<DeconstructResult(const Rational& radius, const Rational& tolerance,
                                                const Rational& precision)>;

// The decider of penshape::deconstruct() on q (q is copied into the returned function).
Decider make_decider(const PolygonSet& q, EngineKind engine, const CancelHook& cancel = {},
                     const DeconstructLimits& limits = {});

struct ToleranceSearchResult {
  Rational radius;
  Rational eps_low;  // ε̂ >= eps_low
  Rational eps_high; // ε̂ <= eps_high; eps_high - eps_low <= Δ when converged
  // The certified solution: YES at tolerance ε̃ = solution.params.tolerance, <= ε̂ + Δ when
  // converged, <= eps_high always.
  DeconstructResult solution;
  // false when the decider broke its UNDECIDED promise and the fallback (if any) did too: then
  // [eps_low, eps_high] is only what the YES and NO answers prove (ε̂ >= the largest ε with a
  // NO, ε̂ <= the smallest with a YES, r at worst: P = Q) and may be wider than Δ.
  bool converged = true;
  // Non-empty when the first decider broke its promise: what it did and what followed.
  std::string note;
  std::size_t decider_calls = 0;  // all calls, the fallback's included
  std::size_t fallback_calls = 0; // of which by the fallback decider
  std::chrono::nanoseconds elapsed{0};
};

// Throws InvalidInput when r or Δ is not positive. When `decide` breaks its guarantee (the final
// certified call did not answer YES), the search is redone with `fallback` (if given) inside
// the bounds the YES and NO answers so far prove; if that breaks too, the result says
// converged = false (see above). Throws std::logic_error only for a decider that contradicts
// itself (a NO above a YES) or gives no YES even at ε = r.
ToleranceSearchResult search_tolerance(const Decider& decide, const Rational& radius,
                                       const Rational& precision, const Decider& fallback = {});

struct RadiusSearchOptions {
  Rational precision;                  // stop when hi - lo <= precision (> 0)
  std::size_t max_decider_calls = 200; // bound on the whole search
  std::size_t max_delta_halvings = 12; // δ goes from ε/2 down to ε/2^(1+this) at one radius
};

struct RadiusSearchResult {
  Rational tolerance;
  // r* ∈ [r_low, r_high]: r_low has a certified YES (or is ε, where P = Q works), r_high a
  // certified NO or the a-priori bound (enclosing radius + ε).
  Rational r_low;
  Rational r_high;
  bool converged = false;            // r_high - r_low <= precision
  DeconstructResult solution_at_low; // the YES at r_low
  std::size_t decider_calls = 0;
  std::size_t undecided_calls = 0;
  std::chrono::nanoseconds elapsed{0};
};

// upper_bound: a radius known to have no solution, e.g. enclosing_radius_bound(q) + ε.
RadiusSearchResult search_radius(const Decider& decide, const Rational& tolerance,
                                 const Rational& upper_bound, const RadiusSearchOptions& options);

// A rational upper bound on the radius of the smallest disk enclosing q (half the bounding
// box's diagonal, rounded up). Beyond it + ε no radius has a solution (Section 4).
Rational enclosing_radius_bound(const PolygonSet& q);

struct SuggestOptions {
  Rational from;                                 // > 0
  Rational to;                                   // > from
  std::size_t samples = 20;                      // >= 3
  Rational relative_precision = Rational(1, 50); // Δ = r · this, per sample
  // Called after each sample with (done, total); return false to stop early.
  std::function<bool(std::size_t, std::size_t)> progress;
  Decider fallback; // passed to search_tolerance for each sample (may be empty)
};

struct RadiusSample {
  Rational radius;
  Rational eps_low;
  Rational eps_high;
  double j = 0.0; // r / ε̂, with ε̂ taken as eps_high (the certified side)
};

struct RadiusSuggestion {
  RadiusSample sample;
  DeconstructResult solution; // certified at sample.eps_high or just above
};

struct SuggestResult {
  std::vector<RadiusSample> samples;         // the J graph
  std::vector<RadiusSuggestion> suggestions; // local maxima of J, best first
  bool stopped_early = false;
  std::size_t decider_calls = 0;
  std::chrono::nanoseconds elapsed{0};
};

SuggestResult suggest_radius(const Decider& decide, const SuggestOptions& options);

} // namespace penshape
