// Translation + rotation against triple-contact brute force.
#include <gtest/gtest.h>

#include "annulus_oracle.hpp"
#include "penshape/core/annulus/rotation.hpp"

namespace penshape::annulus {
namespace {

oracle::Pose pose_of(const Placement& p) { return {p.tx, p.ty, p.theta}; }

TEST(RotationVsOracle, MaxCoverCountsEqualBruteForce) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(0, 1);
  for (unsigned trial = 0; trial < 12; ++trial) {
    const auto poly = oracle::random_convex(rng, 3 + trial % 2, 1.0);
    const TemplatePolygon tp = make_convex_template(poly);
    const auto pts = oracle::points_near(rng, poly, 5, 0.2, {u(rng), u(rng), 6.3 * u(rng)}, 0.3);
    const double delta = 0.05 + 0.2 * u(rng);
    const std::size_t expected = oracle::max_cover_rotation(tp.vertices(), delta, pts);
    const MaxCoverResult r = max_cover_rotation(tp, OuterOffset::kLinearized, delta, pts);
    EXPECT_EQ(r.upper_bound, expected) << "trial " << trial;
    EXPECT_EQ(r.covered.size(), expected) << "trial " << trial;
    // The oracle agrees with the covered set (theta from the exact rotation parameter).
    EXPECT_EQ(oracle::count(tp.vertices(), oracle::Kind::kLinearized, delta, pose_of(r.placement),
                            pts, 1e-9),
              r.covered.size());
  }
}

TEST(RotationVsOracle, MinimumWidthMatchesBruteForce) {
  std::mt19937 rng(37);
  std::uniform_real_distribution<double> u(0, 1);
  for (unsigned trial = 0; trial < 5; ++trial) {
    const auto poly = oracle::random_convex(rng, 3 + trial % 2, 1.0);
    const TemplatePolygon tp = make_convex_template(poly);
    const auto pts = oracle::points_near(rng, poly, 5, 0.15, {u(rng), u(rng), 6.3 * u(rng)});
    const MinWidthResult r = min_width_rotation(tp, OuterOffset::kLinearized, pts);
    // Oracle: bisection on the triple-contact max-cover.
    double lo = 0, hi = r.delta_upper + 0.5;
    while (hi - lo > 1e-9) {
      const double mid = 0.5 * (lo + hi);
      (oracle::max_cover_rotation(tp.vertices(), mid, pts) == pts.size() ? hi : lo) = mid;
    }
    EXPECT_NEAR(r.delta_upper, hi, 1e-6) << "trial " << trial;
    EXPECT_LE(r.delta_lower, hi + 1e-9);
    EXPECT_EQ(oracle::count(tp.vertices(), oracle::Kind::kLinearized, r.delta_upper,
                            pose_of(r.placement), pts, 1e-12),
              pts.size());
    // Rotation can only help.
    const MinWidthResult t = min_width_translation(tp, OuterOffset::kLinearized, pts);
    EXPECT_LE(r.delta_upper, t.delta_upper + 1e-6);
  }
}

TEST(RotationVsOracle, DecisionMatchesBruteForce) {
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> u(0, 1);
  for (unsigned trial = 0; trial < 3; ++trial) {
    const auto poly = oracle::random_convex(rng, 3 + trial % 2, 1.0);
    const TemplatePolygon tp = make_convex_template(poly);
    const auto pts = oracle::points_near(rng, poly, 6, 0.15, {u(rng), u(rng), 6.3 * u(rng)});
    double lo = 0, hi = 2.0;
    while (hi - lo > 1e-6) {
      const double mid = 0.5 * (lo + hi);
      (oracle::max_cover_rotation(tp.vertices(), mid, pts) == pts.size() ? hi : lo) = mid;
    }
    EXPECT_EQ(decide_rotation(tp, OuterOffset::kLinearized, hi * 0.95, pts).answer, Answer::kNo)
        << "trial " << trial;
    const DecisionResult yes = decide_rotation(tp, OuterOffset::kLinearized, hi * 1.05, pts);
    ASSERT_EQ(yes.answer, Answer::kYes) << "trial " << trial;
    EXPECT_EQ(oracle::count(tp.vertices(), oracle::Kind::kLinearized, hi * 1.05,
                            pose_of(yes.placement), pts, 1e-12),
              pts.size());
  }
}

TEST(Rotation, RotatedSquareIsRecovered) {
  // Corners of a square rotated by 30 degrees: exact fit (width 0) only with rotation.
  const TemplatePolygon sq = make_convex_template({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
  const double a = 3.14159265358979 / 6;
  std::vector<PointD> pts;
  for (const PointD& v : sq.vertices()) {
    pts.push_back(
        {std::cos(a) * v.x - std::sin(a) * v.y + 5, std::sin(a) * v.x + std::cos(a) * v.y});
  }
  EXPECT_EQ(decide_rotation(sq, OuterOffset::kLinearized, 1e-6, pts).answer, Answer::kYes);
  EXPECT_EQ(decide_translation(sq, OuterOffset::kLinearized, 0.1, pts).answer, Answer::kNo);
  const MinWidthResult r = min_width_rotation(sq, OuterOffset::kLinearized, pts);
  EXPECT_LT(r.delta_upper, 1e-6);
}

} // namespace
} // namespace penshape::annulus
