// APPROXSEARCHEPS (Algorithm 5) and the certified solution at ε̃ <= ε̂ + Δ, robust to a decider
// whose UNDECIDED breaks the promise of Theorems 11 and 13 (its YES and NO stay proofs).
#include <chrono>
#include <optional>
#include <stdexcept>

#include "penshape/core/search.hpp"

namespace penshape {
namespace {

// What the answers prove whatever the UNDECIDED promise: YES at ε gives ε̂ <= ε, NO gives ε̂ >= ε.
struct Proven {
  Rational no_eps = 0;                  // ε̂ >= no_eps
  std::optional<DeconstructResult> yes; // the YES at the smallest ε

  void record(const Rational& eps, const DeconstructResult& res) {
    if (res.answer == Answer::kNo && eps > no_eps) no_eps = eps;
    if (res.answer == Answer::kYes && (!yes || eps < yes->params.tolerance)) {
      yes = res;
      yes->params.tolerance = eps;
    }
    if (yes && no_eps >= yes->params.tolerance) {
      throw std::logic_error("decider contradicts itself: NO at ε = " + no_eps.get_str() +
                             " at or above a YES at ε = " + yes->params.tolerance.get_str());
    }
  }
};

class Search {
 public:
  Search(const Rational& radius, const Rational& precision, ToleranceSearchResult& out)
      : radius_(radius), precision_(precision), out_(out) {}

  DeconstructResult call(const Decider& decide, const Rational& eps, const Rational& delta) {
    DeconstructResult res = decide(radius_, eps, delta);
    ++out_.decider_calls;
    proven_.record(eps, res);
    return res;
  }

  // Bisection on [lo, hi] then the certified solution into out_; the broken promise if any.
  std::optional<std::string> run(const Decider& decide, Rational lo, Rational hi) {
    while (hi - lo > precision_) {
      const Rational width = hi - lo;
      const Rational mid = (lo + hi) / 2;
      // δ = |I|/8 < mid since mid >= |I|/2: the decider's precondition δ < ε holds.
      switch (call(decide, mid, width / 8).answer) {
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
    out_.eps_low = lo;
    out_.eps_high = hi;
    return certify(decide, lo, hi);
  }

  // The solution: try at ε_yes = hi with δ = |I|/4; if that is undecided, ε̂ >= ε_yes - |I|/2
  // and ε̃ = ε_yes + Δ/2 with δ = Δ/8 must give YES.
  std::optional<std::string> certify(const Decider& decide, const Rational& lo,
                                     const Rational& hi) {
    const Rational width = hi - lo;
    if (sgn(width) > 0) {
      out_.solution = call(decide, hi, width / 4);
      if (out_.solution.answer == Answer::kYes) return std::nullopt;
      if (out_.solution.answer == Answer::kNo) {
        return "NO at ε = " + hi.get_str() + ", the search interval's promised YES end";
      }
    }
    const Rational eps_tilde = hi + precision_ / 2;
    out_.solution = call(decide, eps_tilde, precision_ / 8);
    if (out_.solution.answer == Answer::kYes) return std::nullopt;
    return "no YES at ε̃ = ε_yes + Δ/2 = " + eps_tilde.get_str() + " with δ = Δ/8 (Section 4)";
  }

  // The interval the YES and NO answers prove, with the YES of its upper end (at ε = r if none
  // came: the decider answers r <= ε with P = Q).
  void settle_on_proofs(const Decider& decide) {
    if (!proven_.yes) (void)call(decide, radius_, radius_ / 2);
    if (!proven_.yes) {
      throw std::logic_error("decider gave no YES at ε = r = " + radius_.get_str() +
                             ", where P = Q is a solution");
    }
    out_.converged = false;
    out_.eps_low = proven_.no_eps;
    out_.eps_high = proven_.yes->params.tolerance;
    out_.solution = *proven_.yes;
  }

  Rational proven_low() const { return proven_.no_eps; }
  Rational proven_high() const { return proven_.yes ? proven_.yes->params.tolerance : radius_; }

 private:
  Rational radius_;
  Rational precision_;
  ToleranceSearchResult& out_;
  Proven proven_;
};

} // namespace

ToleranceSearchResult search_tolerance(const Decider& decide, const Rational& radius,
                                       const Rational& precision, const Decider& fallback) {
  if (sgn(radius) <= 0) throw InvalidInput("radius must be positive, got " + radius.get_str());
  if (sgn(precision) <= 0) {
    throw InvalidInput("precision Δ must be positive, got " + precision.get_str());
  }
  const auto start = std::chrono::steady_clock::now();
  ToleranceSearchResult out;
  out.radius = radius;
  Search search(radius, precision, out);
  // ε̂ <= r: at ε = r, P = Q is a solution.
  std::optional<std::string> broken = search.run(decide, Rational(0), radius);
  if (broken) {
    out.note = "the decider broke its UNDECIDED promise (" + *broken + ")";
    if (fallback) {
      const std::size_t before = out.decider_calls;
      const Rational lo = search.proven_low();
      const Rational hi = search.proven_high();
      broken = search.run(fallback, lo, hi);
      out.fallback_calls = out.decider_calls - before;
      out.note += "; searched again with the fallback decider within the proven [" + lo.get_str() +
                  ", " + hi.get_str() + "]";
      if (broken) out.note += ", which broke it too (" + *broken + ")";
    }
  }
  if (broken) {
    search.settle_on_proofs(fallback ? fallback : decide);
    out.note += "; the interval is what the YES and NO answers prove";
  }
  out.elapsed = std::chrono::steady_clock::now() - start;
  return out;
}

} // namespace penshape
