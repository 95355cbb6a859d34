// APPROXSEARCHEPS (Algorithm 5) and the certified solution at ε̃ <= ε̂ + Δ.
#include <chrono>

#include "penshape/core/search.hpp"

namespace penshape {

ToleranceSearchResult search_tolerance(const Decider& decide, const Rational& radius,
                                       const Rational& precision) {
  if (sgn(radius) <= 0) throw InvalidInput("radius must be positive, got " + radius.get_str());
  if (sgn(precision) <= 0) {
    throw InvalidInput("precision Δ must be positive, got " + precision.get_str());
  }
  const auto start = std::chrono::steady_clock::now();
  ToleranceSearchResult out;
  out.radius = radius;
  Rational lo = 0;
  Rational hi = radius; // ε̂ <= r: at ε = r, P = Q is a solution
  while (hi - lo > precision) {
    const Rational width = hi - lo;
    const Rational mid = (lo + hi) / 2;
    // δ = |I|/8 < mid since mid >= |I|/2: the decider's precondition δ < ε holds.
    const DeconstructResult res = decide(radius, mid, width / 8);
    ++out.decider_calls;
    switch (res.answer) {
      case Answer::kYes:
        hi = mid;
        break;
      case Answer::kNo:
        lo = mid;
        break;
      case Answer::kUndecided:
        // Theorems 11 and 13: |mid - ε̂| <= 2δ = |I|/4.
        lo = mid - width / 4;
        hi = mid + width / 4;
        break;
    }
  }
  out.eps_low = lo;
  out.eps_high = hi;

  // The solution: try at ε_yes with δ = |I|/4; if that is undecided, ε̂ >= ε_yes - |I|/2 and
  // ε̃ = ε_yes + Δ/2 with δ = Δ/8 must give YES.
  const Rational width = hi - lo;
  if (sgn(width) > 0) {
    out.solution = decide(radius, hi, width / 4);
    ++out.decider_calls;
  }
  if (out.solution.answer != Answer::kYes) {
    if (out.solution.answer == Answer::kNo && sgn(width) > 0) {
      throw InvalidInput("decider broke its guarantee: NO at ε = " + hi.get_str() +
                         ", the search interval's certified YES end");
    }
    const Rational eps_tilde = hi + precision / 2;
    out.solution = decide(radius, eps_tilde, precision / 8);
    ++out.decider_calls;
    if (out.solution.answer != Answer::kYes) {
      throw InvalidInput("decider broke its guarantee: no YES at ε̃ = ε_yes + Δ/2 = " +
                         eps_tilde.get_str() + " with δ = Δ/8 (Section 4)");
    }
  }
  out.elapsed = std::chrono::steady_clock::now() - start;
  return out;
}

} // namespace penshape
