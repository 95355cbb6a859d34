// The fast engine's certified answers against independent checks: the authors' demo cases and
// the shared polygons (shared corpus, skipped without it), generated polygons of known answer
// and the generated suite, dense-sampling verification of every YES solution, consistency of
// answers across eps and delta on random polygons, and clear errors at the documented limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <string>

#include "engine/engines.hpp"
#include "fast_test_support.hpp"
#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_io.hpp"
#include "polygon_gen.hpp"
#include "test_data.hpp"

namespace penshape {
namespace {

using fast_test::check_yes;
using fast_test::read_polygon_file;

DeconstructParams params_of(const Rational& r, const Rational& eps, const Rational& delta) {
  DeconstructParams p;
  p.radius = r;
  p.tolerance = eps;
  p.precision = delta;
  return p;
}

PolygonSet generated(const gen::GenPolygon& g) {
  PolygonSet q = read_polygon_text(g.text);
  normalize_orientation(q);
  return q;
}

// A generated YES case at r = 1, eps = 1/10: a convex hexagon offset by 1 (chords within 0.02).
PolygonSet rounded_hexagon() { return generated(gen::rounded_convex(8, 6, 10.0, 1.0, 0.02).q); }

DeconstructResult decide(const PolygonSet& q, const DeconstructParams& p) {
  return detail::decide_fast(q, p, {}, {});
}

Rational width(const PolygonSet& q) {
  Rational lo = q.polygons[0].outer[0].x, hi = lo;
  for (const auto& poly : q.polygons) {
    for (const auto& v : poly.outer) {
      lo = std::min(lo, v.x);
      hi = std::max(hi, v.x);
    }
  }
  return hi - lo;
}

// Every YES: the solution's r-offset is eps-close to Q at every sampled point.
void expect_yes_solution_checks(const PolygonSet& q, const DeconstructResult& res,
                                const std::string& what) {
  ASSERT_EQ(res.answer, Answer::kYes) << what;
  ASSERT_FALSE(res.solution.empty()) << what;
  EXPECT_LE(res.hausdorff_bound, res.params.tolerance) << what;
  const double r = res.params.radius.get_d(), eps = res.params.tolerance.get_d();
  const fast_test::YesCheck c = check_yes(q, res.solution, r, eps, eps / 6.0);
  const double tiny = 1e-9 * (r + eps);
  EXPECT_LE(c.q_excess, tiny) << what << ": a point of Q is farther than r + eps from P";
  EXPECT_LE(c.p_excess, tiny) << what << ": a point of offset(P, r) is farther than eps from Q";
  EXPECT_GT(c.samples, 100U) << what;
}

TEST(FastEngine, AuthorsDemoCases) {
  PENSHAPE_SHARED_OR_SKIP(polygons, "polygons");
  const std::string dir = polygons.string() + "/";
  const Rational r = 1, eps(1, 10);
  for (const char* name : {"authors_demo_1_01_work1.txt", "authors_demo_1_01_work2.txt"}) {
    const PolygonSet q = read_polygon_file(dir + name);
    const DeconstructResult res = decide(q, params_of(r, eps, eps / 8));
    expect_yes_solution_checks(q, res, name);
  }
  {
    const PolygonSet q = read_polygon_file(dir + "authors_demo_1_01_fail1.txt");
    EXPECT_EQ(decide(q, params_of(r, eps, eps / 8)).answer, Answer::kNo);
  }
  {
    // Corners cut by 1/4 need a finer precision than 1/3 (the authors' note).
    const PolygonSet q = read_polygon_file(dir + "authors_demo_1_01_fail2.txt");
    EXPECT_NE(decide(q, params_of(r, eps, eps / 8)).answer, Answer::kYes);
    EXPECT_EQ(decide(q, params_of(r, eps, eps / 64)).answer, Answer::kNo);
  }
}

// An independent closed form for NO and YES: for a square (fail1, side 5 > 2r) the largest
// admissible P is Π = the square shrunk by r - eps (the disk of radius r fits into the
// eps-rounded corner), and the corner of Q is covered by offset(Π, r + eps) iff
// sqrt(2) (r - eps) <= r + eps, i.e. eps >= eps_hat = (sqrt(2) - 1)^2 r ≈ 0.1716 r.
// With delta below |eps - eps_hat| / 2 the answer is decided (Theorems 11, 13).
TEST(FastEngine, SquareMatchesTheClosedFormThreshold) {
  const PolygonSet q{{{{{0, 0}, {5, 0}, {5, 5}, {0, 5}}, {}}}}; // the demo's fail1 square
  const double eps_hat = (std::sqrt(2.0) - 1.0) * (std::sqrt(2.0) - 1.0);
  for (const int hundredths : {10, 14, 16}) {
    const Rational eps(hundredths, 100);
    ASSERT_LT(eps.get_d(), eps_hat);
    EXPECT_EQ(decide(q, params_of(1, eps, Rational(1, 1000))).answer, Answer::kNo) << hundredths;
  }
  for (const int hundredths : {19, 25, 50}) {
    const Rational eps(hundredths, 100);
    ASSERT_GT(eps.get_d(), eps_hat);
    expect_yes_solution_checks(q, decide(q, params_of(1, eps, Rational(1, 1000))),
                               "square eps=" + std::to_string(hundredths) + "/100");
  }
}

void expect_checked_at_three_radii(const PolygonSet& q, const std::string& name) {
  ASSERT_FALSE(q.empty()) << name;
  const Rational w = width(q);
  for (const int div : {10, 30, 50}) {
    const Rational r = w / div, eps = r / 2;
    const std::string what = name + " r=w/" + std::to_string(div);
    const DeconstructResult res = decide(q, params_of(r, eps, eps / 8));
    if (res.answer == Answer::kYes) expect_yes_solution_checks(q, res, what);
    EXPECT_TRUE(res.answer != Answer::kYes || res.solution.vertex_count() >= 3) << what;
  }
}

TEST(FastEngine, SharedPolygonsAtThreeRadii) {
  PENSHAPE_SHARED_OR_SKIP(dir, "polygons");
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".txt") continue;
    expect_checked_at_three_radii(read_polygon_file(entry.path().string()),
                                  entry.path().filename().string());
  }
}

// The interior chain first insets a simplified stage-1 region a little deeper (faster); a thin
// Π̂ can vanish there, and the chain then insets the region itself as it used to. The authors'
// S (width 273) at r = 364, eps = 3r/4 is such a case: Π̂ is a sliver, YES only through the
// second candidate.
TEST(FastEngine, ThinInteriorCandidateIsStillFound) {
  PENSHAPE_SHARED_OR_SKIP(file, "polygons/authors_S.txt");
  const PolygonSet q = read_polygon_file(file.string());
  ASSERT_EQ(width(q), Rational(273));
  const Rational r = 364, eps = r * 3 / 4;
  expect_yes_solution_checks(q, decide(q, params_of(r, eps, eps / 8)), "authors_S r=364");
}

TEST(FastEngine, GeneratedPolygonsAtThreeRadii) {
  for (const auto& g : gen::polygon_suite(23)) expect_checked_at_three_radii(generated(g), g.name);
}

void expect_approximable_at_half_radius(const PolygonSet& q, const std::string& what) {
  const Rational r = width(q) / 30, eps = r / 2;
  const DeconstructResult res = decide(q, params_of(r, eps, eps / 8));
  expect_yes_solution_checks(q, res, what);
  // Far fewer vertices than the input (the point of deconstruction).
  EXPECT_LT(res.solution.vertex_count(), q.vertex_count() / 2);
}

TEST(FastEngine, KazakhstanIsApproximableAtHalfRadius) {
  PENSHAPE_SHARED_OR_SKIP(file, "polygons/kazakhstan_paper1881.txt");
  expect_approximable_at_half_radius(read_polygon_file(file.string()), "kazakhstan w/30");
}

TEST(FastEngine, GeneratedCountryIsApproximableAtHalfRadius) {
  expect_approximable_at_half_radius(generated(gen::country(4, 1881, 1000.0)), "country w/30");
}

// Certified answers never contradict: YES at eps1 and NO at eps2 > eps1 is impossible, and
// no two precisions disagree at the same eps.
TEST(FastEngine, RandomPolygonsAnswersConsistentAcrossEpsAndDelta) {
  std::mt19937 rng(20261122);
  int yes = 0, no = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const PolygonSet q = fast_test::random_star_polygon(rng, 8 + trial % 20, 10.0);
    const Rational r(1 + trial % 3, 2);
    Answer previous = Answer::kNo;
    Rational previous_eps = 0;
    for (int k = 1; k <= 7; ++k) {
      const Rational eps = r * Rational(k, 8);
      Answer at_eps = Answer::kUndecided;
      for (const int div : {4, 16}) {
        const DeconstructResult res = decide(q, params_of(r, eps, eps / div));
        if (res.answer == Answer::kYes) {
          expect_yes_solution_checks(q, res, "random trial " + std::to_string(trial));
          ++yes;
        }
        if (res.answer == Answer::kNo) ++no;
        if (res.answer != Answer::kUndecided) {
          EXPECT_TRUE(at_eps == Answer::kUndecided || at_eps == res.answer)
              << "trial " << trial << " eps " << eps.get_d() << ": precisions disagree";
          at_eps = res.answer;
        }
      }
      // Monotone in eps: once YES, never NO at a larger eps.
      if (previous == Answer::kYes) {
        EXPECT_NE(at_eps, Answer::kNo) << "trial " << trial << " YES at " << previous_eps.get_d()
                                       << " but NO at " << eps.get_d();
      }
      if (at_eps != Answer::kUndecided) {
        previous = at_eps == Answer::kYes ? Answer::kYes : previous;
        previous_eps = eps;
      }
    }
  }
  // The sweep must exercise both certified answers.
  EXPECT_GT(yes, 10);
  EXPECT_GT(no, 5);
}

TEST(FastEngine, HugeCoordinatesWithSmallExtentWork) {
  // A far-away copy of a YES case: the grid frame translates it.
  PolygonSet q = rounded_hexagon();
  const Rational shift(mpz_class("1000000000000"), 1);
  for (auto& v : q.polygons[0].outer) v.x += shift;
  const DeconstructResult res = decide(q, params_of(1, Rational(1, 10), Rational(1, 80)));
  expect_yes_solution_checks(q, res, "shifted work1");
}

TEST(FastEngine, ExtentTooLargeForPrecisionIsAClearError) {
  PolygonSet q = rounded_hexagon();
  for (auto& v : q.polygons[0].outer) v.x *= Rational(mpz_class("1000000000"), 1);
  try {
    decide(q, params_of(1, Rational(1, 10), Rational(1, 80)));
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("2^24 times the precision"), std::string::npos)
        << e.what();
  }
}

TEST(FastEngine, TinyPrecisionHitsTheDiskLimit) {
  const PolygonSet q = rounded_hexagon();
  DeconstructLimits limits;
  limits.max_disk_vertices = 64;
  try {
    detail::decide_fast(q, params_of(1, Rational(1, 10), Rational(1, 100000)), {}, limits);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("over the limit of 64"), std::string::npos) << e.what();
  }
}

TEST(FastEngine, CancelHookStopsTheComputation) {
  const PolygonSet q = generated(gen::country(4, 1881, 1000.0));
  const Rational r = width(q) / 30;
  EXPECT_THROW(detail::decide_fast(q, params_of(r, r / 2, r / 16), [] { return true; }, {}),
               Cancelled);
}

// deconstruct() orients Q before the engine and tells it so (the engine then skips its own
// check): a clockwise copy of a polygon gets the answer and solution of the polygon itself.
TEST(FastEngine, ClockwiseInputIsOrientedOnceBeforeTheEngine) {
  const PolygonSet q = generated(gen::country(4, 400, 1000.0));
  PolygonSet clockwise = q;
  std::reverse(clockwise.polygons[0].outer.begin(), clockwise.polygons[0].outer.end());
  const Rational r = width(q) / 30;
  const DeconstructParams p = params_of(r, r / 2, r / 16);
  const DeconstructResult want = deconstruct(q, p);
  const DeconstructResult got = deconstruct(clockwise, p);
  ASSERT_EQ(want.answer, Answer::kYes);
  EXPECT_EQ(got.answer, want.answer);
  ASSERT_EQ(got.solution.polygons.size(), want.solution.polygons.size());
  for (std::size_t i = 0; i < want.solution.polygons.size(); ++i) {
    EXPECT_EQ(got.solution.polygons[i].outer, want.solution.polygons[i].outer);
    EXPECT_EQ(got.solution.polygons[i].holes, want.solution.polygons[i].holes);
  }
}

} // namespace
} // namespace penshape
