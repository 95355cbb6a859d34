// The radii with a solution form [0, r*] (Theorem 21); a bisection that bounds its own
// refinement, since persistent UNDECIDED answers cannot be refined away (Section 4).
#include <chrono>

#include "penshape/core/search.hpp"

namespace penshape {
namespace {

// APPROXDECIDE at radius r, halving δ from ε/2 while UNDECIDED, at most `halvings` times.
DeconstructResult decide_refining(const Decider& decide, const Rational& r, const Rational& eps,
                                  const RadiusSearchOptions& options, RadiusSearchResult& out) {
  Rational delta = eps / 2;
  DeconstructResult res;
  for (std::size_t i = 0; i <= options.max_delta_halvings; ++i) {
    if (out.decider_calls >= options.max_decider_calls) break;
    res = decide(r, eps, delta);
    ++out.decider_calls;
    if (res.answer != Answer::kUndecided) return res;
    ++out.undecided_calls;
    delta /= 2;
  }
  res.answer = Answer::kUndecided;
  return res;
}

} // namespace

RadiusSearchResult search_radius(const Decider& decide, const Rational& tolerance,
                                 const Rational& upper_bound, const RadiusSearchOptions& options) {
  if (sgn(tolerance) <= 0) {
    throw InvalidInput("tolerance must be positive, got " + tolerance.get_str());
  }
  if (sgn(options.precision) <= 0) {
    throw InvalidInput("radius precision must be positive, got " + options.precision.get_str());
  }
  if (upper_bound <= tolerance) {
    throw InvalidInput("radius upper bound must exceed the tolerance, got " +
                       upper_bound.get_str());
  }
  const auto start = std::chrono::steady_clock::now();
  RadiusSearchResult out;
  out.tolerance = tolerance;
  // r <= ε always has the solution P = Q.
  out.r_low = tolerance;
  out.solution_at_low = decide(tolerance, tolerance, tolerance / 2);
  ++out.decider_calls;
  out.r_high = upper_bound;

  // `probe` moves towards r_high after a persistent UNDECIDED: r* is the *largest* radius with
  // ε̂(r) <= ε, so undecided ground near r_low says little about it.
  Rational probe_from = out.r_low;
  while (out.r_high - out.r_low > options.precision &&
         out.decider_calls < options.max_decider_calls) {
    if (out.r_high - probe_from <= options.precision) break; // only undecided ground is left
    const Rational mid = (probe_from + out.r_high) / 2;
    DeconstructResult res = decide_refining(decide, mid, tolerance, options, out);
    if (res.answer == Answer::kYes) {
      out.r_low = mid;
      probe_from = mid;
      out.solution_at_low = std::move(res);
    } else if (res.answer == Answer::kNo) {
      out.r_high = mid;
    } else {
      probe_from = mid;
    }
  }
  out.converged = out.r_high - out.r_low <= options.precision;
  out.elapsed = std::chrono::steady_clock::now() - start;
  return out;
}

Rational enclosing_radius_bound(const PolygonSet& q) {
  if (q.empty() || q.polygons.front().outer.empty()) return Rational(0);
  ExactPoint lo = q.polygons.front().outer.front();
  ExactPoint hi = lo;
  for (const auto& poly : q.polygons) {
    for (const auto& p : poly.outer) { // holes lie inside outers
      if (p.x < lo.x) lo.x = p.x;
      if (p.y < lo.y) lo.y = p.y;
      if (p.x > hi.x) hi.x = p.x;
      if (p.y > hi.y) hi.y = p.y;
    }
  }
  // The enclosing radius is at most half the diagonal sqrt(w² + h²) / 2 <= (w + h) / 2, which
  // is rational.
  return ((hi.x - lo.x) + (hi.y - lo.y)) / 2;
}

} // namespace penshape
