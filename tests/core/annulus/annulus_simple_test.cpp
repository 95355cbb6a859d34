// Simple (non-convex) templates, Section 5, against the brute-force oracle.
#include <gtest/gtest.h>

#include "annulus_oracle.hpp"
#include "penshape/core/annulus/translation.hpp"

namespace penshape::annulus {
namespace {

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

TEST(SimpleTemplateVsOracle, MaxCoverCountsEqualBruteForce) {
  std::mt19937 rng(53);
  std::uniform_real_distribution<double> u(0, 1);
  int nonconvex = 0;
  for (unsigned trial = 0; trial < 30; ++trial) {
    const auto poly = random_star(rng, 5 + trial % 3);
    const TemplatePolygon tp = make_simple_template(poly);
    bool convex = true;
    try {
      make_convex_template(poly);
    } catch (const InvalidInput&) {
      convex = false;
    }
    nonconvex += convex ? 0 : 1;
    const auto pts = oracle::points_near(rng, poly, 6, 0.2, {u(rng), u(rng), 0.0}, 0.2);
    const double delta = 0.05 + 0.2 * u(rng);
    const std::size_t expected =
        oracle::max_cover_translation(tp.vertices(), oracle::Kind::kSimple, delta, pts);
    const MaxCoverResult r = max_cover_translation(tp, OuterOffset::kRound, delta, pts);
    EXPECT_EQ(r.upper_bound, expected) << "trial " << trial;
    EXPECT_EQ(r.covered.size(), expected) << "trial " << trial;
    const oracle::Pose pose{r.placement.tx, r.placement.ty, 0};
    EXPECT_EQ(oracle::count(tp.vertices(), oracle::Kind::kSimple, delta, pose, pts, 1e-9),
              expected);
  }
  EXPECT_GT(nonconvex, 10);
}

TEST(SimpleTemplateVsOracle, MinimumWidthMatchesBruteForce) {
  std::mt19937 rng(59);
  std::uniform_real_distribution<double> u(0, 1);
  for (unsigned trial = 0; trial < 8; ++trial) {
    const auto poly = random_star(rng, 5 + trial % 2);
    const TemplatePolygon tp = make_simple_template(poly);
    const auto pts = oracle::points_near(rng, poly, 5, 0.15, {u(rng), u(rng), 0.0});
    const MinWidthResult r = min_width_translation(tp, OuterOffset::kRound, pts);
    const double expected = oracle::min_width_translation(tp.vertices(), oracle::Kind::kSimple, pts,
                                                          r.delta_upper + 1.0);
    EXPECT_NEAR(r.delta_upper, expected, 1e-6) << "trial " << trial;
    const oracle::Pose pose{r.placement.tx, r.placement.ty, 0};
    EXPECT_EQ(oracle::count(tp.vertices(), oracle::Kind::kSimple, r.delta_upper, pose, pts, 1e-12),
              pts.size());
  }
}

TEST(SimpleTemplate, LShapeNeedsTheNotch) {
  // Points along an L-shaped outline fit an L template tightly, but its convex hull poorly.
  const std::vector<PointD> L{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}};
  const TemplatePolygon tp = make_simple_template(L);
  std::vector<PointD> pts;
  for (std::size_t k = 0; k < L.size(); ++k) {
    const PointD a = L[k], b = L[(k + 1) % L.size()];
    for (int t = 0; t < 10; ++t) {
      pts.push_back({a.x + (b.x - a.x) * t / 10.0 + 7, a.y + (b.y - a.y) * t / 10.0 - 3});
    }
  }
  const MinWidthResult r = min_width_translation(tp, OuterOffset::kRound, pts);
  EXPECT_LT(r.delta_upper, 1e-6);
  const TemplatePolygon hull = make_convex_template({{0, 0}, {4, 0}, {4, 1}, {1, 4}, {0, 4}});
  EXPECT_GT(min_width_translation(hull, OuterOffset::kRound, pts).delta_upper, 0.5);
}

} // namespace
} // namespace penshape::annulus
