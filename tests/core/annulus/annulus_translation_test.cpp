// Translation algorithms against the brute-force oracle on small random inputs.
#include <gtest/gtest.h>

#include "annulus_oracle.hpp"
#include "penshape/core/annulus/translation.hpp"

namespace penshape::annulus {
namespace {

oracle::Kind kind_of(OuterOffset o) {
  return o == OuterOffset::kRound ? oracle::Kind::kRound : oracle::Kind::kLinearized;
}

// Every reported covered point is in the annulus by the oracle's measure, and no other is.
void expect_cover_valid(const std::vector<PointD>& poly, oracle::Kind kind, double delta,
                        const MaxCoverResult& r, const std::vector<PointD>& pts) {
  const oracle::Pose pose{r.placement.tx, r.placement.ty, r.placement.theta};
  std::size_t next = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double m = oracle::measure(poly, kind, oracle::to_template(pose, pts[i]));
    const bool listed = next < r.covered.size() && r.covered[next] == i;
    if (listed) ++next;
    if (std::abs(m - delta) > 1e-9) {
      EXPECT_EQ(listed, m <= delta) << "point " << i;
    }
  }
}

class TranslationVsOracle : public ::testing::TestWithParam<OuterOffset> {};

TEST_P(TranslationVsOracle, MaxCoverCountsEqualBruteForce) {
  const OuterOffset outer = GetParam();
  std::mt19937 rng(7u + static_cast<unsigned>(outer));
  std::uniform_real_distribution<double> u(0, 1);
  for (unsigned trial = 0; trial < 40; ++trial) {
    const std::size_t m = 3 + trial % 4;
    const auto poly = oracle::random_convex(rng, m, 1.0);
    const TemplatePolygon tp = make_convex_template(poly);
    const auto pts =
        oracle::points_near(rng, poly, 5 + trial % 4, 0.25, {u(rng), u(rng), 0.0}, 0.3);
    const double delta = 0.05 + 0.3 * u(rng);
    const std::size_t expected =
        oracle::max_cover_translation(tp.vertices(), kind_of(outer), delta, pts);
    for (bool bucketing : {true, false}) {
      const MaxCoverResult r = max_cover_translation(tp, outer, delta, pts, {bucketing});
      EXPECT_EQ(r.upper_bound, expected) << "trial " << trial;
      EXPECT_EQ(r.covered.size(), expected) << "trial " << trial;
      expect_cover_valid(tp.vertices(), kind_of(outer), delta, r, pts);
    }
  }
}

TEST_P(TranslationVsOracle, MinimumWidthMatchesBruteForce) {
  const OuterOffset outer = GetParam();
  std::mt19937 rng(11u + static_cast<unsigned>(outer));
  std::uniform_real_distribution<double> u(0, 1);
  for (unsigned trial = 0; trial < 15; ++trial) {
    const auto poly = oracle::random_convex(rng, 3 + trial % 3, 1.0);
    const TemplatePolygon tp = make_convex_template(poly);
    const auto pts = oracle::points_near(rng, poly, 4 + trial % 3, 0.2, {u(rng), u(rng), 0.0});
    const MinWidthResult r = min_width_translation(tp, outer, pts);
    const double expected =
        oracle::min_width_translation(tp.vertices(), kind_of(outer), pts, r.delta_upper + 1.0);
    // Stated tolerance: relative 1e-8 of the problem scale (about 4 here) plus the oracle's.
    EXPECT_NEAR(r.delta_upper, expected, 1e-6) << "trial " << trial;
    EXPECT_LE(r.delta_lower, expected + 1e-9);
    EXPECT_LE(r.delta_upper - r.delta_lower, 1e-6);
    // The placement is valid at delta_upper by the oracle's own measure.
    const oracle::Pose pose{r.placement.tx, r.placement.ty, 0};
    EXPECT_EQ(oracle::count(tp.vertices(), kind_of(outer), r.delta_upper, pose, pts, 1e-12),
              pts.size());
  }
}

TEST_P(TranslationVsOracle, DecisionMatchesBruteForce) {
  const OuterOffset outer = GetParam();
  std::mt19937 rng(23u + static_cast<unsigned>(outer));
  std::uniform_real_distribution<double> u(0, 1);
  for (unsigned trial = 0; trial < 20; ++trial) {
    const auto poly = oracle::random_convex(rng, 3 + trial % 4, 1.0);
    const TemplatePolygon tp = make_convex_template(poly);
    const auto pts = oracle::points_near(rng, poly, 5, 0.2, {u(rng), u(rng), 0.0});
    const double opt = oracle::min_width_translation(tp.vertices(), kind_of(outer), pts, 3.0);
    for (double f : {0.9, 1.1}) {
      const DecisionResult d = decide_translation(tp, outer, opt * f, pts);
      EXPECT_EQ(d.answer, f < 1 ? Answer::kNo : Answer::kYes) << "trial " << trial;
      if (d.answer == Answer::kYes) {
        const oracle::Pose pose{d.placement.tx, d.placement.ty, 0};
        EXPECT_EQ(oracle::count(tp.vertices(), kind_of(outer), opt * f, pose, pts, 1e-12),
                  pts.size());
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Outer, TranslationVsOracle,
                         ::testing::Values(OuterOffset::kRound, OuterOffset::kLinearized));

TEST(Translation, DuplicatesAndSinglePoint) {
  const TemplatePolygon sq = make_convex_template({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  const std::vector<PointD> one{{5, 5}};
  EXPECT_EQ(max_cover_translation(sq, OuterOffset::kRound, 0.0, one).covered.size(), 1u);
  EXPECT_EQ(decide_translation(sq, OuterOffset::kRound, 0.01, one).answer, Answer::kYes);
  const std::vector<PointD> dup{{1, 1}, {1, 1}, {1, 1}, {9, 9}};
  const MaxCoverResult r = max_cover_translation(sq, OuterOffset::kLinearized, 0.1, dup);
  EXPECT_EQ(r.covered.size(), 3u);
  // The four corners of a 2x2 square fit exactly with delta 0; a point in the middle does not
  // fit with delta < 1 (it is 1 away from every edge).
  const std::vector<PointD> corners{{10, 10}, {12, 10}, {12, 12}, {10, 12}, {11, 11}};
  const MinWidthResult w = min_width_translation(sq, OuterOffset::kRound, corners);
  EXPECT_NEAR(w.delta_upper, 0.5, 1e-6); // shift by 0.5: centre and corners balance
  EXPECT_EQ(decide_translation(sq, OuterOffset::kRound, 0.4, corners).answer, Answer::kNo);
}

} // namespace
} // namespace penshape::annulus
