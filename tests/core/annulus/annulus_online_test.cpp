// The on-line decision equals the off-line decision on every prefix.
#include <gtest/gtest.h>

#include <cmath>

#include "annulus_oracle.hpp"
#include "penshape/core/annulus/online.hpp"
#include "penshape/core/annulus/translation.hpp"

namespace penshape::annulus {
namespace {

class OnlineVsOffline : public ::testing::TestWithParam<OuterOffset> {};

TEST_P(OnlineVsOffline, EveryPrefixAgrees) {
  const OuterOffset outer = GetParam();
  std::mt19937 rng(41u + static_cast<unsigned>(outer));
  std::uniform_real_distribution<double> u(0, 1);
  std::size_t no_answers = 0;
  std::size_t yes_answers = 0;
  for (unsigned trial = 0; trial < 25; ++trial) {
    const auto poly = oracle::random_convex(rng, 3 + trial % 5, 1.0);
    const TemplatePolygon tp = make_convex_template(poly);
    auto pts = oracle::points_near(rng, poly, 30, 0.12, {2 * u(rng), u(rng), 0.0}, 0.03);
    const double delta = 0.08 + 0.08 * u(rng);
    OnlineContainment online(tp, outer, delta, 10.0);
    std::vector<PointD> prefix;
    for (const PointD& q : pts) {
      prefix.push_back(q);
      const Answer on = online.add(q);
      const Answer off = decide_translation(tp, outer, delta, prefix).answer;
      ASSERT_EQ(on, off) << "trial " << trial << " prefix " << prefix.size();
      if (on == Answer::kYes) {
        ++yes_answers;
        EXPECT_EQ(covered_exactly(tp, outer, delta, online.placement(), prefix).size(),
                  prefix.size());
        // Independent check of the witness.
        const oracle::Pose pose{online.placement().tx, online.placement().ty, 0};
        EXPECT_EQ(oracle::count(tp.vertices(),
                                outer == OuterOffset::kRound ? oracle::Kind::kRound
                                                             : oracle::Kind::kLinearized,
                                delta, pose, prefix, 1e-12),
                  prefix.size());
      }
      no_answers += on == Answer::kNo ? 1 : 0;
    }
    EXPECT_LE(online.max_active_structures(), pts.size());
  }
  // The inputs exercise both answers.
  EXPECT_GT(no_answers, 20u);
  EXPECT_GT(yes_answers, 20u);
}

INSTANTIATE_TEST_SUITE_P(Outer, OnlineVsOffline,
                         ::testing::Values(OuterOffset::kRound, OuterOffset::kLinearized));

// Batches (add_all) answer as the off-line decision on the same points, whatever the split.
TEST_P(OnlineVsOffline, BatchesAgree) {
  const OuterOffset outer = GetParam();
  std::mt19937 rng(77u + static_cast<unsigned>(outer));
  std::uniform_real_distribution<double> u(0, 1);
  std::size_t no_answers = 0, yes_answers = 0;
  for (unsigned trial = 0; trial < 25; ++trial) {
    const auto poly = oracle::random_convex(rng, 3 + trial % 5, 1.0);
    const TemplatePolygon tp = make_convex_template(poly);
    const auto pts = oracle::points_near(rng, poly, 30, 0.12, {2 * u(rng), u(rng), 0.0}, 0.03);
    const double delta = 0.08 + 0.08 * u(rng);
    OnlineContainment online(tp, outer, delta, 10.0);
    std::vector<PointD> prefix;
    std::size_t at = 0;
    while (at < pts.size()) {
      const std::size_t take = std::min<std::size_t>(1 + rng() % 9, pts.size() - at);
      const std::vector<PointD> batch(pts.begin() + static_cast<std::ptrdiff_t>(at),
                                      pts.begin() + static_cast<std::ptrdiff_t>(at + take));
      at += take;
      prefix.insert(prefix.end(), batch.begin(), batch.end());
      const Answer on = online.add_all(batch);
      const Answer off = decide_translation(tp, outer, delta, prefix).answer;
      ASSERT_EQ(on, off) << "trial " << trial << " prefix " << prefix.size();
      ASSERT_EQ(online.points(), prefix.size());
      if (on == Answer::kYes) {
        ++yes_answers;
        const oracle::Pose pose{online.placement().tx, online.placement().ty, 0};
        EXPECT_EQ(oracle::count(tp.vertices(),
                                outer == OuterOffset::kRound ? oracle::Kind::kRound
                                                             : oracle::Kind::kLinearized,
                                delta, pose, prefix, 1e-12),
                  prefix.size());
      }
      no_answers += on == Answer::kNo ? 1 : 0;
    }
  }
  EXPECT_GT(no_answers, 5u);
  EXPECT_GT(yes_answers, 5u);
}

TEST(Online, BatchWithANonFinitePointAddsNothing) {
  const TemplatePolygon sq = make_convex_template({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  OnlineContainment online(sq, OuterOffset::kRound, 0.5, 20.0);
  const std::vector<PointD> bad{{0, 0}, {NAN, 1}};
  EXPECT_THROW(online.add_all(bad), InvalidInput);
  EXPECT_EQ(online.points(), 0u);
  EXPECT_EQ(online.add_all(std::vector<PointD>{}), Answer::kUndecided);
}

// A random star-shaped (simple, usually non-convex) polygon.
std::vector<PointD> random_star(std::mt19937& rng, std::size_t m) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<PointD> v;
  for (std::size_t k = 0; k < m; ++k) {
    const double a =
        2 * 3.14159265358979 * (static_cast<double>(k) + 0.3 * u(rng)) / static_cast<double>(m);
    const double r = 0.25 + 1.25 * u(rng);
    v.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return v;
}

// Simple templates (Section 5, kRound): the on-line answer equals the off-line decision on
// every prefix, whether points come one by one or in batches, and YES witnesses pass the
// brute-force oracle.
TEST(OnlineSimple, EveryPrefixAgreesWithOffline) {
  std::mt19937 rng(97);
  std::uniform_real_distribution<double> u(0, 1);
  std::size_t no_answers = 0, yes_answers = 0;
  int nonconvex = 0;
  for (unsigned trial = 0; trial < 24; ++trial) {
    const auto poly = random_star(rng, 5 + trial % 3);
    const TemplatePolygon tp = make_simple_template(poly);
    try {
      (void)make_convex_template(poly);
    } catch (const InvalidInput&) {
      ++nonconvex;
    }
    const auto pts = oracle::points_near(rng, poly, 14, 0.12, {u(rng), u(rng), 0.0}, 0.05);
    const double delta = 0.06 + 0.12 * u(rng);
    OnlineContainment one_by_one(tp, OuterOffset::kRound, delta, 10.0);
    OnlineContainment batched(tp, OuterOffset::kRound, delta, 10.0);
    std::vector<PointD> prefix;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      prefix.push_back(pts[i]);
      const Answer on = one_by_one.add(pts[i]);
      const Answer off = decide_translation(tp, OuterOffset::kRound, delta, prefix).answer;
      ASSERT_EQ(on, off) << "trial " << trial << " prefix " << prefix.size();
      if (i % 3 == 2 || i + 1 == pts.size()) {
        const std::size_t from = i - std::min<std::size_t>(i, i % 3);
        const std::vector<PointD> batch(pts.begin() + static_cast<std::ptrdiff_t>(from),
                                        pts.begin() + static_cast<std::ptrdiff_t>(i + 1));
        ASSERT_EQ(batched.add_all(batch), off) << "trial " << trial << " prefix " << i + 1;
      }
      if (on == Answer::kYes) {
        ++yes_answers;
        const oracle::Pose pose{one_by_one.placement().tx, one_by_one.placement().ty, 0};
        EXPECT_EQ(oracle::count(tp.vertices(), oracle::Kind::kSimple, delta, pose, prefix, 1e-12),
                  prefix.size());
      }
      no_answers += on == Answer::kNo ? 1 : 0;
    }
    EXPECT_LE(one_by_one.max_active_structures(), pts.size());
  }
  EXPECT_GT(nonconvex, 8);
  EXPECT_GT(no_answers, 10u);
  EXPECT_GT(yes_answers, 10u);
}

TEST(OnlineSimple, LinearizedNeedsAConvexTemplate) {
  const TemplatePolygon l = make_simple_template({{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}});
  EXPECT_THROW(OnlineContainment(l, OuterOffset::kLinearized, 0.2, 10.0), InvalidInput);
  OnlineContainment round(l, OuterOffset::kRound, 0.2, 10.0);
  // Points along the L's boundary fit; a point in the middle of the L's inner corner region
  // (far from every edge) cannot join them.
  for (const PointD q : {PointD{0, 0}, PointD{4, 0}, PointD{0, 4}, PointD{1, 2}, PointD{3, 1}}) {
    EXPECT_EQ(round.add(q), Answer::kYes);
  }
  EXPECT_EQ(round.add({2.5, 2.5}), Answer::kNo);
  EXPECT_EQ(round.add({0, 0}), Answer::kNo); // final
}

TEST(Online, PruningKeepsFewStructures) {
  // Many points on a square's boundary: most points cannot touch the annulus boundary of a
  // containing placement, so they are discarded (Section 4.3).
  const TemplatePolygon sq = make_convex_template({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  std::mt19937 rng(3);
  const auto pts = oracle::points_near(rng, sq.vertices(), 400, 0.2, {3, 4, 0});
  OnlineContainment online(sq, OuterOffset::kRound, 0.5, 20.0);
  for (const PointD& q : pts) EXPECT_EQ(online.add(q), Answer::kYes);
  EXPECT_LT(online.active_structures(), 100u);
  EXPECT_EQ(online.points(), 400u);
}

} // namespace
} // namespace penshape::annulus
