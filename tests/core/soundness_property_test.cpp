// The soundness promise of issue 22 on generated inputs with features at and below the fast
// engine's grid scale (soundness_generator.hpp, fixed seeds): the default engine (fast, the
// convex path, and the reference fallback) never contradicts the reference engine, and the
// independent verifier (penshape verify) accepts every YES and NO it gives; the ε̂ search
// brackets consistently. The count scales with PENSHAPE_SOUNDNESS_CASES (default 3000, a tenth
// under sanitizers); every `reference_every`-th case is also decided by the reference engine.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_io.hpp"
#include "penshape/core/search.hpp"
#include "penshape/core/verify.hpp"
#include "soundness_generator.hpp"
#include "test_data.hpp"

namespace penshape {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

std::uint64_t case_count() {
  if (const char* v = std::getenv("PENSHAPE_SOUNDNESS_CASES")) return std::strtoull(v, nullptr, 10);
  return kSanitized ? 300 : 3000;
}

bool contradict(Answer a, Answer b) {
  return (a == Answer::kYes && b == Answer::kNo) || (a == Answer::kNo && b == Answer::kYes);
}

bool decisive(Answer a) { return a != Answer::kUndecided; }

// What the verifier says of an answer ("" when accepted or UNDECIDED).
std::string refusal(const PolygonSet& q, const DeconstructResult& res) {
  if (!decisive(res.answer)) return "";
  const DeconstructionClaim claim{res.answer,           res.params.radius, res.params.tolerance,
                                  res.params.precision, res.solution,      res.no_witness};
  const VerifyReport rep = verify_deconstruction(q, claim);
  return rep.status == VerifyStatus::kVerified ? "" : rep.message;
}

std::string describe(std::uint64_t seed, const test::SoundnessCase& c) {
  return "seed " + std::to_string(seed) + " (" + c.kind + ", eps " + c.params.tolerance.get_str() +
         "): " + to_wkt(c.q);
}

struct Tally {
  std::array<int, 3> answers{}; // YES, NO, UNDECIDED of the default engine
  int by_reference = 0;         // default answers the reference fallback gave
  int compared = 0, reference_decisive = 0, both_decisive = 0;
};

TEST(SoundnessProperty, DefaultEngineAgreesWithReferenceAndVerifier) {
  const std::uint64_t n = case_count();
  const std::uint64_t reference_every = 3;
  std::map<std::string, Tally> tallies;
  int invalid = 0, undecided_shown = 0;
  for (std::uint64_t seed = 0; seed < n; ++seed) {
    const test::SoundnessCase c = test::make_soundness_case(seed);
    try {
      validate_deconstruct_input(c.q, c.params);
    } catch (const InvalidInput&) {
      ++invalid;
      continue;
    }
    Tally& t = tallies[c.kind];
    const DeconstructResult res = deconstruct(c.q, c.params);
    ++t.answers[static_cast<std::size_t>(res.answer)];
    if (decisive(res.answer) && res.engine == EngineKind::kReference) ++t.by_reference;
    const std::string why = refusal(c.q, res);
    EXPECT_EQ(why, "") << to_string(res.answer) << " by " << to_string(res.engine) << " refuted, "
                       << describe(seed, c);
    if (seed % reference_every != 0) continue;
    DeconstructParams ref = c.params;
    ref.engine = EngineKind::kReference;
    const DeconstructResult b = deconstruct(c.q, ref);
    EXPECT_FALSE(contradict(res.answer, b.answer))
        << to_string(res.answer) << " vs reference " << to_string(b.answer) << ", "
        << describe(seed, c);
    ++t.compared;
    if (decisive(b.answer)) {
      ++t.reference_decisive;
      if (decisive(res.answer)) {
        ++t.both_decisive;
      } else if (++undecided_shown <= 5) {
        std::printf("default UNDECIDED, reference %s: %s\n", to_string(b.answer),
                    describe(seed, c).c_str());
      }
    }
  }
  std::printf("%-22s %5s %5s %5s %6s %8s %8s\n", "kind", "YES", "NO", "UND", "by ref", "ref dec",
              "both");
  int ref_dec = 0, both = 0, total = 0;
  for (const auto& [kind, t] : tallies) {
    std::printf("%-22s %5d %5d %5d %6d %8d %8d\n", kind.c_str(), t.answers[0], t.answers[1],
                t.answers[2], t.by_reference, t.reference_decisive, t.both_decisive);
    ref_dec += t.reference_decisive;
    both += t.both_decisive;
    total += t.answers[0] + t.answers[1] + t.answers[2];
  }
  std::printf("%d cases (%d invalid skipped); default decisive on %d of %d the reference decides\n",
              total, invalid, both, ref_dec);
  EXPECT_GT(total, static_cast<int>(n * 8 / 10)) << "the generator makes too many invalid cases";
  EXPECT_GE(both * 10, ref_dec * 9) << "the default engine must decide >= 90% of these";
}

// The two inputs of issue 22 (tests/data/adversarial): the former fast engine answered a false
// YES and a false NO. Now the fast engine proves the NO itself (an exact vertex of the sliver is
// the witness), and the YES, which needs the sliver's share of Π, comes from the reference
// engine; each answer names its engine and is verified.
TEST(SoundnessProperty, IssueInputsAnswerRightAndNameTheEngine) {
  const DeconstructParams params{1, Rational(1, 2), Rational(1, 16), EngineKind::kFast};
  const struct {
    const char* file;
    Answer answer;
    EngineKind engine;
  } cases[] = {{"sliver_false_yes.txt", Answer::kNo, EngineKind::kFast},
               {"sliver_false_no.txt", Answer::kYes, EngineKind::kReference}};
  for (const auto& c : cases) {
    const PolygonSet q =
        read_polygon_text(test::read_file(test::bundled_data_dir() / "adversarial" / c.file));
    const DeconstructResult res = deconstruct(q, params);
    EXPECT_EQ(res.answer, c.answer) << c.file;
    EXPECT_EQ(res.engine, c.engine) << c.file;
    EXPECT_EQ(refusal(q, res), "") << c.file;
  }
}

// The ε̂ and radius searches on a sample of the cases: their solutions are verified, and the
// reference engine gives no YES where their NO answers put the other end of the bracket.
TEST(SoundnessProperty, ToleranceSearchBracketsConsistently) {
  const std::uint64_t n = std::max<std::uint64_t>(case_count() / 50, 6);
  for (std::uint64_t k = 0; k < n; ++k) {
    const std::uint64_t seed = k * 7 + 1;
    const test::SoundnessCase c = test::make_soundness_case(seed);
    try {
      validate_deconstruct_input(c.q, c.params);
    } catch (const InvalidInput&) {
      continue;
    }
    const Rational r = c.params.radius;
    const ToleranceSearchResult s = search_tolerance(
        make_decider(c.q, EngineKind::kFast), r, r / 64, make_decider(c.q, EngineKind::kReference));
    ASSERT_EQ(s.solution.answer, Answer::kYes) << describe(seed, c);
    EXPECT_EQ(refusal(c.q, s.solution), "") << describe(seed, c);
    EXPECT_LE(s.eps_low, s.eps_high) << describe(seed, c);
    if (sgn(s.eps_low) > 0 && s.eps_low < r) {
      const DeconstructResult low =
          deconstruct(c.q, {r, s.eps_low, s.eps_low / 8, EngineKind::kReference});
      EXPECT_NE(low.answer, Answer::kYes) << "reference YES below eps_low, " << describe(seed, c);
    }
    // The radius search at this case's eps: its YES at r_low is verified, and the reference
    // engine gives no YES at r_high when a NO (not the a-priori bound) put it there.
    const Rational eps = c.params.tolerance;
    const Rational bound = enclosing_radius_bound(c.q) + eps;
    const RadiusSearchResult rs =
        search_radius(make_decider(c.q, EngineKind::kFast), eps, bound, {r / 16, 40, 6});
    EXPECT_LE(rs.r_low, rs.r_high) << describe(seed, c);
    if (rs.solution_at_low.answer == Answer::kYes) {
      EXPECT_EQ(refusal(c.q, rs.solution_at_low), "") << describe(seed, c);
    }
    if (rs.r_high < bound && rs.r_high > eps) {
      const DeconstructResult high =
          deconstruct(c.q, {rs.r_high, eps, eps / 8, EngineKind::kReference});
      EXPECT_NE(high.answer, Answer::kYes) << "reference YES at r_high, " << describe(seed, c);
    }
  }
}

} // namespace
} // namespace penshape
