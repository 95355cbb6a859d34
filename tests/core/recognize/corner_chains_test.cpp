// The closed corner search (corners.cpp) finds every corner count in one dynamic programme: each
// count's chain must be the one a search for that count alone finds, and on a polygon drawn
// exactly, its corners. PreparedStroke keeps the chains made on first use; a count beyond them
// makes them again.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "recognize/fitting/fit.hpp"

namespace penshape::recognize_detail {
namespace {

constexpr double kPi = std::numbers::pi;

// A wobbly closed stroke around a rounded polygon of `corners` corners.
std::vector<PointD> wobbly_outline(std::mt19937& rng, std::size_t corners) {
  std::uniform_real_distribution<double> wobble(-0.8, 0.8);
  std::vector<PointD> pts;
  for (std::size_t i = 0; i < 48; ++i) {
    const double a = 2 * kPi * static_cast<double>(i) / 48.0;
    const double bump = 1.0 + 0.15 * std::cos(static_cast<double>(corners) * a);
    pts.push_back({20 * bump * std::cos(a) + wobble(rng), 20 * bump * std::sin(a) + wobble(rng)});
  }
  return pts;
}

TEST(ClosedCornerChains, EveryCountIsTheChainOfASearchForThatCountAlone) {
  std::mt19937 rng(11);
  for (std::size_t shape = 3; shape <= 8; ++shape) {
    for (int trial = 0; trial < 20; ++trial) {
      const std::vector<PointD> pts = wobbly_outline(rng, shape);
      const auto all = closed_corner_chains(pts, kMaxPolygonCorners);
      ASSERT_EQ(all.size(), kMaxPolygonCorners + 1);
      for (std::size_t k = 3; k <= kMaxPolygonCorners; ++k) {
        ASSERT_EQ(all[k].size(), k);
        EXPECT_EQ(all[k], closed_corner_chains(pts, k)[k]) << shape << " " << trial << " " << k;
      }
    }
  }
}

TEST(ClosedCornerChains, AnExactPolygonsChainIsItsCorners) {
  for (std::size_t k = 3; k <= kMaxPolygonCorners; ++k) {
    // Each side sampled evenly from its first corner: the corners are points k * side.
    const std::size_t side = 6;
    std::vector<PointD> pts;
    for (std::size_t c = 0; c < k; ++c) {
      const double a0 = 2 * kPi * static_cast<double>(c) / static_cast<double>(k) + 0.3;
      const double a1 = 2 * kPi * static_cast<double>(c + 1) / static_cast<double>(k) + 0.3;
      const PointD p{30 * std::cos(a0), 30 * std::sin(a0)};
      const PointD q{30 * std::cos(a1), 30 * std::sin(a1)};
      for (std::size_t i = 0; i < side; ++i) {
        const double f = static_cast<double>(i) / static_cast<double>(side);
        pts.push_back(p + f * (q - p));
      }
    }
    std::vector<std::size_t> chain = closed_corner_chains(pts, kMaxPolygonCorners)[k];
    std::sort(chain.begin(), chain.end());
    std::vector<std::size_t> corners;
    for (std::size_t c = 0; c < k; ++c) corners.push_back(c * side);
    EXPECT_EQ(chain, corners) << k << " corners";
  }
}

TEST(ClosedCornerChains, TooFewPointsGiveNoChain) {
  const std::vector<PointD> pts{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0.5}, {0.5, 0}, {0.5, 1}};
  const auto chains = closed_corner_chains(pts, 5);
  EXPECT_EQ(chains[3].size(), 3U); // 7 points hold 3 corners (2 points each)
  EXPECT_TRUE(chains[4].empty());
  EXPECT_TRUE(chains[5].empty());
  EXPECT_TRUE(closed_corner_chains({{0, 0}, {1, 0}, {1, 1}}, 3)[3].empty());
}

TEST(ClosedCornerChains, APreparedStrokeKeepsItsChainsAndMakesMoreOnDemand) {
  std::mt19937 rng(5);
  PreparedStroke s = prepare_points(wobbly_outline(rng, 5), 0.0);
  const auto expected = closed_corner_chains(s.fit_points, 12);
  EXPECT_EQ(closed_corners(s, 4), expected[4]);
  EXPECT_EQ(s.closed_corner_chains.size(), kMaxPolygonCorners + 1); // made for every count once
  EXPECT_EQ(closed_corners(s, 7), expected[7]);
  EXPECT_EQ(closed_corners(s, 12), expected[12]); // beyond them: made again, up to 12
  EXPECT_EQ(s.closed_corner_chains.size(), 13U);
  EXPECT_EQ(closed_corners(s, 3), expected[3]);
}

} // namespace
} // namespace penshape::recognize_detail
