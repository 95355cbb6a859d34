// The search algorithms against synthetic deciders that know ε̂(r) exactly and answer as
// adversarially as Theorems 11 and 13 allow: any UNDECIDED within 2δ of ε̂, YES or NO beyond.
// This checks the searches' invariants independently of any geometry.
#include <gtest/gtest.h>

#include <random>

#include "penshape/core/search.hpp"

namespace penshape {
namespace {

using EpsHat = std::function<Rational(const Rational&)>;

struct Adversary {
  EpsHat eps_hat;
  std::mt19937 rng{12345};
  std::size_t calls = 0;

  DeconstructResult operator()(const Rational& r, const Rational& eps, const Rational& delta) {
    ++calls;
    EXPECT_GT(delta, 0);
    EXPECT_LT(delta, eps) << "decider precondition δ < ε";
    DeconstructResult res;
    res.params = {r, eps, delta, EngineKind::kReference};
    const Rational e = eps_hat(r);
    const bool coin = std::uniform_int_distribution<int>(0, 1)(rng) == 1;
    if (r <= eps || eps - e >= 2 * delta) {
      res.answer = Answer::kYes; // P = Q, or Theorem 11 forces YES
    } else if (e - eps >= 2 * delta) {
      res.answer = Answer::kNo; // Theorem 13 forces NO
    } else if (eps >= e) {
      res.answer = coin ? Answer::kYes : Answer::kUndecided;
    } else {
      res.answer = coin ? Answer::kNo : Answer::kUndecided;
    }
    return res;
  }
};

Decider as_decider(Adversary& a) {
  return [&a](const Rational& r, const Rational& e, const Rational& d) { return a(r, e, d); };
}

TEST(SearchTolerance, IntervalHoldsEpsHatAndSolutionIsWithinDelta) {
  for (int seed = 0; seed < 40; ++seed) {
    Adversary adv;
    adv.rng.seed(static_cast<unsigned>(seed));
    const Rational target(37 + seed, 100); // ε̂ for r = 1 (< r)
    adv.eps_hat = [target](const Rational&) { return Rational(target); };
    const Rational delta(1, 1000);
    const ToleranceSearchResult res = search_tolerance(as_decider(adv), Rational(1), delta);
    EXPECT_LE(res.eps_low, target) << seed;
    EXPECT_GE(res.eps_high, target) << seed;
    EXPECT_LE(res.eps_high - res.eps_low, delta);
    ASSERT_EQ(res.solution.answer, Answer::kYes);
    EXPECT_LE(res.solution.params.tolerance, target + delta);
    EXPECT_GE(res.solution.params.tolerance, target);
    EXPECT_EQ(res.decider_calls, adv.calls);
    EXPECT_LE(res.decider_calls, 16U); // log2(1 / Δ) + 2
  }
}

TEST(SearchTolerance, ZeroEpsHat) {
  Adversary adv;
  adv.eps_hat = [](const Rational&) { return Rational(0); };
  const auto res = search_tolerance(as_decider(adv), Rational(2), Rational(1, 100));
  EXPECT_EQ(res.eps_low, 0);
  EXPECT_EQ(res.solution.answer, Answer::kYes);
  EXPECT_LE(res.solution.params.tolerance, Rational(1, 100));
}

// A decider whose UNDECIDED breaks the promise (it stays UNDECIDED wherever r > ε) and gives
// no fallback: the search must not throw but return what its answers prove, [0, r], with the
// YES at r (P = Q), and say it did not converge.
TEST(SearchTolerance, BrokenDeciderIsReportedNotTrusted) {
  const Decider never_yes = [](const Rational& r, const Rational& e, const Rational& d) {
    DeconstructResult res;
    res.params = {r, e, d, EngineKind::kFast};
    res.answer = r <= e ? Answer::kYes : Answer::kUndecided;
    return res;
  };
  const auto res = search_tolerance(never_yes, Rational(1), Rational(1, 1000));
  EXPECT_FALSE(res.converged);
  EXPECT_NE(res.note.find("broke"), std::string::npos) << res.note;
  EXPECT_EQ(res.eps_low, 0);
  EXPECT_EQ(res.eps_high, 1);
  EXPECT_EQ(res.solution.answer, Answer::kYes);
  EXPECT_EQ(res.solution.params.tolerance, 1);
  EXPECT_EQ(res.fallback_calls, 0U);
  EXPECT_THROW((void)search_tolerance(never_yes, Rational(0), Rational(1, 10)), InvalidInput);
  EXPECT_THROW((void)search_tolerance(never_yes, Rational(1), Rational(0)), InvalidInput);
}

// The slit case: the first decider is honest except that it stays UNDECIDED on a band far above
// ε̂ (a completeness gap: its YES and NO stay true). The search notices at its final call and
// redoes itself with the fallback inside the proven bounds: converged, ε̂ inside, width <= Δ.
TEST(SearchTolerance, FallbackSettlesABrokenPromise) {
  for (int seed = 0; seed < 20; ++seed) {
    const Rational target(17, 100);
    Adversary honest;
    honest.rng.seed(static_cast<unsigned>(seed));
    honest.eps_hat = [target](const Rational&) { return Rational(target); };
    const Decider gappy = [&honest](const Rational& r, const Rational& e, const Rational& d) {
      DeconstructResult res = honest(r, e, d);
      if (e > Rational(1, 4) && e < Rational(3, 5)) res.answer = Answer::kUndecided;
      return res;
    };
    Adversary reference;
    reference.rng.seed(static_cast<unsigned>(seed + 100));
    reference.eps_hat = honest.eps_hat;
    const Rational delta(1, 256);
    const auto res = search_tolerance(gappy, Rational(1), delta, as_decider(reference));
    EXPECT_TRUE(res.converged) << seed << ": " << res.note;
    EXPECT_FALSE(res.note.empty());
    EXPECT_LE(res.eps_low, target) << seed;
    EXPECT_GE(res.eps_high, target) << seed;
    EXPECT_LE(res.eps_high - res.eps_low, delta) << seed;
    ASSERT_EQ(res.solution.answer, Answer::kYes);
    EXPECT_LE(res.solution.params.tolerance, target + delta);
    EXPECT_GT(res.fallback_calls, 0U);
    EXPECT_EQ(res.fallback_calls, reference.calls);
    EXPECT_EQ(res.decider_calls, honest.calls + reference.calls);
  }
}

// Without a fallback the same gap leaves the interval the YES and NO answers prove: it holds ε̂
// (no UNDECIDED-derived bound survives) and the solution is the smallest YES seen.
TEST(SearchTolerance, WithoutFallbackTheProvenIntervalHoldsEpsHat) {
  for (int seed = 0; seed < 20; ++seed) {
    const Rational target(17, 100);
    Adversary honest;
    honest.rng.seed(static_cast<unsigned>(seed));
    honest.eps_hat = [target](const Rational&) { return Rational(target); };
    const Decider gappy = [&honest](const Rational& r, const Rational& e, const Rational& d) {
      DeconstructResult res = honest(r, e, d);
      if (e > Rational(1, 4) && e < Rational(3, 5)) res.answer = Answer::kUndecided;
      return res;
    };
    const auto res = search_tolerance(gappy, Rational(1), Rational(1, 256));
    EXPECT_FALSE(res.converged) << seed;
    EXPECT_LE(res.eps_low, target) << seed;
    EXPECT_GE(res.eps_high, target) << seed;
    ASSERT_EQ(res.solution.answer, Answer::kYes);
    EXPECT_EQ(res.solution.params.tolerance, res.eps_high);
  }
}

TEST(SearchTolerance, SelfContradictingDeciderIsAnInternalError) {
  // NO everywhere below r and YES at r is consistent (ε̂ = r).
  const Decider no_below = [](const Rational& r, const Rational& e, const Rational& d) {
    DeconstructResult res;
    res.params = {r, e, d, EngineKind::kFast};
    res.answer = r <= e ? Answer::kYes : Answer::kNo;
    return res;
  };
  const auto fine = search_tolerance(no_below, Rational(1), Rational(1, 64));
  EXPECT_TRUE(fine.converged);
  EXPECT_EQ(fine.eps_high, 1);
  // A YES at the first midpoint 1/2, NO ever after: the certified call at ε_yes = 1/2 answers
  // NO where a YES was given, which no sound decider can do.
  std::size_t calls = 0;
  const Decider liar = [&](const Rational& r, const Rational& e, const Rational& d) {
    DeconstructResult res = no_below(r, e, d);
    if (calls++ == 0) res.answer = Answer::kYes;
    return res;
  };
  EXPECT_THROW((void)search_tolerance(liar, Rational(1), Rational(1, 64)), std::logic_error);
}

TEST(SearchRadius, BoundsHoldRStar) {
  // ε̂(r) = max(0, (r - 2) / 2): monotone, 1-Lipschitz. For ε = 1/2, r* = 3.
  for (int seed = 0; seed < 20; ++seed) {
    Adversary adv;
    adv.rng.seed(static_cast<unsigned>(seed));
    adv.eps_hat = [](const Rational& r) -> Rational {
      return r > 2 ? Rational((r - 2) / 2) : Rational(0);
    };
    RadiusSearchOptions opt;
    opt.precision = Rational(1, 1000);
    const auto res = search_radius(as_decider(adv), Rational(1, 2), Rational(20), opt);
    EXPECT_LE(res.r_low, Rational(3)) << seed;
    EXPECT_GE(res.r_high, Rational(3)) << seed;
    EXPECT_TRUE(res.converged) << seed;
    EXPECT_EQ(res.solution_at_low.answer, Answer::kYes);
    EXPECT_EQ(res.solution_at_low.params.radius, res.r_low);
  }
}

TEST(SearchRadius, FlatEpsHatStopsWithHonestBounds) {
  // ε̂(r) = ε on [2, 5]: r* = 5, and every probe inside is undecided at any δ. The search must
  // stop within its call budget and still bracket r*.
  const Rational eps(1, 2);
  Adversary adv;
  adv.eps_hat = [eps](const Rational& r) -> Rational {
    if (r < 2) return Rational(eps * r / 2);
    if (r <= 5) return Rational(eps);
    return Rational(eps + (r - 5));
  };
  // Make the adversary maximally unhelpful: always UNDECIDED when allowed.
  const Decider stubborn = [&adv](const Rational& r, const Rational& e, const Rational& d) {
    DeconstructResult res = adv(r, e, d);
    if (r > e && res.answer != Answer::kUndecided) {
      const Rational gap = e - adv.eps_hat(r);
      if (gap < 2 * d && -gap < 2 * d) res.answer = Answer::kUndecided;
    }
    return res;
  };
  RadiusSearchOptions opt;
  opt.precision = Rational(1, 100);
  opt.max_decider_calls = 300;
  const auto res = search_radius(stubborn, eps, Rational(10), opt);
  EXPECT_LE(res.r_low, Rational(5));
  EXPECT_GE(res.r_high, Rational(5));
  EXPECT_LE(res.decider_calls, opt.max_decider_calls);
  EXPECT_GT(res.undecided_calls, 0U);
}

TEST(SearchRadius, RejectsBadParameters) {
  Adversary adv;
  adv.eps_hat = [](const Rational&) { return Rational(0); };
  RadiusSearchOptions opt;
  opt.precision = Rational(1, 10);
  EXPECT_THROW((void)search_radius(as_decider(adv), Rational(0), Rational(5), opt), InvalidInput);
  EXPECT_THROW((void)search_radius(as_decider(adv), Rational(1), Rational(1, 2), opt),
               InvalidInput);
  opt.precision = 0;
  EXPECT_THROW((void)search_radius(as_decider(adv), Rational(1), Rational(5), opt), InvalidInput);
}

TEST(SuggestRadius, FindsTheLocalMaximaOfJ) {
  // ε̂(r) with a dip near r = 3: J = r/ε̂ peaks there and at the top of the range.
  Adversary adv;
  adv.eps_hat = [](const Rational& r) -> Rational {
    const Rational d = r > 3 ? Rational(r - 3) : Rational(3 - r);
    return Rational(1, 10) + d / 4; // 1/4-Lipschitz, positive
  };
  SuggestOptions opt;
  opt.from = Rational(1);
  opt.to = Rational(5);
  opt.samples = 9;
  std::size_t progress_calls = 0;
  opt.progress = [&](std::size_t done, std::size_t total) {
    ++progress_calls;
    EXPECT_EQ(total, 9U);
    EXPECT_EQ(done, progress_calls);
    return true;
  };
  const auto res = suggest_radius(as_decider(adv), opt);
  EXPECT_EQ(progress_calls, 9U);
  ASSERT_EQ(res.samples.size(), 9U);
  ASSERT_FALSE(res.suggestions.empty());
  EXPECT_EQ(res.suggestions.front().sample.radius, Rational(3));
  EXPECT_EQ(res.suggestions.front().solution.answer, Answer::kYes);
  for (const auto& s : res.samples) {
    const Rational e = adv.eps_hat(s.radius);
    EXPECT_LE(s.eps_low, e);
    EXPECT_GE(s.eps_high, e);
  }
}

TEST(SuggestRadius, StopsWhenProgressSaysSo) {
  Adversary adv;
  adv.eps_hat = [](const Rational& r) -> Rational { return r / 3; };
  SuggestOptions opt;
  opt.from = Rational(1);
  opt.to = Rational(2);
  opt.samples = 10;
  opt.progress = [](std::size_t done, std::size_t) { return done < 4; };
  const auto res = suggest_radius(as_decider(adv), opt);
  EXPECT_TRUE(res.stopped_early);
  EXPECT_EQ(res.samples.size(), 4U);
}

TEST(EnclosingRadiusBound, CoversTheBoundingBox) {
  PolygonSet q;
  q.polygons.push_back({{{Rational(0), Rational(0)},
                         {Rational(4), Rational(0)},
                         {Rational(4), Rational(3)},
                         {Rational(0), Rational(3)}},
                        {}});
  const Rational b = enclosing_radius_bound(q);
  EXPECT_GE(b * b, Rational(25, 4)); // half the diagonal, 5/2
}

} // namespace
} // namespace penshape
