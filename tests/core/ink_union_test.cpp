// Clipper's union as the ink polygon runs it (core/src/ink/ink_union.hpp) measured against the
// exact union with exact rational arithmetic. On adversarial unions (thin strips crossing at every
// angle, nearly parallel ones, coordinates up to 10^17 grid units) a lower bound on the Hausdorff
// distance between Clipper's output O and the exact union S of its inputs is computed exactly: the
// distance of every vertex of O outside S to S, and of every exact crossing of input edges and
// every input vertex outside O to O. At 10^17 that distance exceeds the half grid diagonal the grid
// term counts (so the union needs its arithmetic term), and it stays within the half diagonal plus
// clipper_union_arithmetic; at drawing-sized coordinates within the half diagonal alone. The ink
// bound itself adds the term once per union.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "exact_union.hpp"
#include "ink/ink_union.hpp"
#include "penshape/core/ink.hpp"

namespace penshape {
namespace {

using ClipperLib::cInt;
using ClipperLib::Path;
using ClipperLib::Paths;

// A platform-independent uniform number in [-1, 1).
double symmetric(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1p-52 - 1.0; }

// Three thin strips (length 0.6 M, width about 2 units or 10^-6 M) through random points within
// 0.3 M, at random angles, or (flat) at angles within `flat` of the x axis.
Paths strips(std::mt19937_64& g, double m, double flat) {
  Paths out;
  for (int k = 0; k < 3; ++k) {
    const double cx = symmetric(g) * m * 0.3, cy = symmetric(g) * m * 0.3, half = m * 0.3;
    const double w = (2 + symmetric(g)) * std::max(1.0, m * 1e-6);
    const double angle = flat > 0 && k < 2 ? symmetric(g) * flat : symmetric(g) * std::numbers::pi;
    const double c = std::cos(angle), s = std::sin(angle);
    const auto at = [](double v) { return static_cast<cInt>(std::llround(v)); };
    Path p{{at(cx - half * c - w * s), at(cy - half * s + w * c)},
           {at(cx + half * c - w * s), at(cy + half * s + w * c)},
           {at(cx + half * c + w * s), at(cy + half * s - w * c)},
           {at(cx - half * c + w * s), at(cy - half * s - w * c)}};
    if (ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
    out.push_back(p);
  }
  return out;
}

double worst_error(double m, double flat, int trials, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  double worst = 0;
  for (int t = 0; t < trials; ++t)
    worst = std::max(worst, test::union_error_lower_bound(strips(g, m, flat)));
  return worst;
}

constexpr double kHalfDiagonal = std::numbers::sqrt2 / 2;

TEST(InkUnion, HugeCoordinatesNeedTheArithmeticTermAndStayWithinIt) {
  const double m = 1e17;
  const double worst = worst_error(m, 0.0, 60, 1);
  EXPECT_GT(worst, kHalfDiagonal) << "grid rounding alone would cover this union";
  EXPECT_LE(worst, kHalfDiagonal + ink_detail::clipper_union_arithmetic(m));
}

TEST(InkUnion, NearlyParallelEdgesStayWithinTheBound) {
  for (const double m : {1e15, 1e17, 1e18}) {
    const double worst = worst_error(m, 1e-9, 30, 2);
    EXPECT_LE(worst, kHalfDiagonal + ink_detail::clipper_union_arithmetic(m)) << m;
  }
}

TEST(InkUnion, DrawingSizedCoordinatesStayWithinHalfADiagonal) {
  for (const double flat : {0.0, 1e-3, 1e-5}) {
    const double worst = worst_error(3e5, flat, 200, 3);
    EXPECT_LE(worst, kHalfDiagonal + ink_detail::clipper_union_arithmetic(3e5)) << flat;
  }
}

// The ink bound counts the term once per union: an offset stroke's own union and the final union
// of several strokes (here far from the origin on a fine grid: 10^17 grid units).
TEST(InkUnion, InkBoundCountsEveryUnion) {
  std::vector<std::vector<InkSample>> strokes;
  for (int s = 0; s < 2; ++s) {
    std::vector<InkSample> stroke;
    stroke.reserve(20);
    for (int i = 0; i < 20; ++i)
      stroke.push_back({1e8 + i * 1e-5, 1e8 + s * 2e-6 + i * 1e-7, 1e-6});
    strokes.push_back(stroke);
  }
  InkOptions options;
  options.radius_mm = 1e-6;
  options.max_error_mm = 1e-8;
  const InkPolygon ink = ink_polygon(strokes, options);
  const double units = (1e8 + 2e-4) / ink.grid;
  ASSERT_GT(units, 1e16);
  // 64 u M per union (ink_union.hpp), two unions; the other terms are far smaller here.
  EXPECT_GE(ink.hausdorff_bound, 2 * 64 * 0x1p-53 * units * ink.grid);
}

} // namespace
} // namespace penshape
