// The default tolerance follows the drawing, not the pen (issue 23): epsilon = min(f * size +
// k * r, f_max * size) (recognize.hpp), so a fine pen on a large drawing still snaps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape {
namespace {

// A square of side `side` drawn as one stroke whose sides wobble by `wobble` (sine waves across
// the side, 3 periods).
std::vector<StrokePoint> wobbly_square(double side, double wobble) {
  std::vector<StrokePoint> out;
  const double corners[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  for (int s = 0; s < 4; ++s) {
    const double dx = corners[s + 1][0] - corners[s][0], dy = corners[s + 1][1] - corners[s][1];
    for (int k = 0; k < 60; ++k) {
      const double f = k / 60.0;
      const double w = wobble * std::sin(3 * 2 * std::numbers::pi * f);
      out.push_back({side * (corners[s][0] + f * dx) - w * dy,
                     side * (corners[s][1] + f * dy) + w * dx,
                     0.01 * static_cast<double>(out.size())});
    }
  }
  out.push_back({0, 0, 0.01 * static_cast<double>(out.size())});
  return out;
}

TEST(ToleranceRule, SizeTermPlusPenBoundedBySize) {
  const RecognizerConfig c;
  const std::vector<StrokePoint> p{{0, 0, 0}, {300, 400, 1}}; // size 500
  RecognizerConfig fine = c;
  fine.pen_radius = 0.25;
  EXPECT_DOUBLE_EQ(choose_tolerance(p, fine).epsilon,
                   std::min(c.tolerance_size_fraction * 500 + c.tolerance_pen_radii * 0.25,
                            c.max_tolerance_fraction * 500));
  RecognizerConfig wide = c;
  wide.pen_radius = 1000; // a pen far wider than the mark: bounded by the size
  EXPECT_DOUBLE_EQ(choose_tolerance(p, wide).epsilon, c.max_tolerance_fraction * 500);
  // No pen given: r = default_pen_radius_fraction * size.
  const ToleranceChoice none = choose_tolerance(p, c);
  EXPECT_DOUBLE_EQ(none.pen_radius, c.default_pen_radius_fraction * 500);
  EXPECT_DOUBLE_EQ(
      none.epsilon,
      std::min(
          (c.tolerance_size_fraction + c.tolerance_pen_radii * c.default_pen_radius_fraction) * 500,
          c.max_tolerance_fraction * 500));
  // An explicit tolerance overrides the rule.
  RecognizerConfig given = c;
  given.tolerance = 3;
  EXPECT_DOUBLE_EQ(choose_tolerance(p, given).epsilon, 3);
}

TEST(ToleranceRule, FollowsTheDrawingNotThePen) {
  // The same drawing at 15 and 150 mm with a 0.25 mm pen: epsilon grows tenfold (it follows the
  // size), and never falls below f * size however fine the pen (the former rule gave 5 R).
  const RecognizerConfig c;
  for (const double side : {15.0, 150.0}) {
    RecognizerConfig fine = c;
    fine.pen_radius = 0.25;
    const ToleranceChoice t = choose_tolerance(wobbly_square(side, 0), fine);
    EXPECT_GE(t.epsilon, c.tolerance_size_fraction * t.size) << side;
  }
}

TEST(ToleranceRule, FinePenOnALargeSquareSnaps) {
  // 150 mm square, wobble 2% of its side, 0.25 mm pen: the former min(5 R, 12.5%) gave
  // epsilon = 1.25 mm against a 3 mm wobble (freeform); the drawing's size decides now.
  RecognizerConfig fine;
  fine.pen_radius = 0.25;
  const Recognition r = recognize(wobbly_square(150, 3), fine);
  EXPECT_TRUE(r.shape == ShapeClass::kSquare || r.shape == ShapeClass::kRectangle ||
              r.shape == ShapeClass::kQuadrilateral)
      << to_string(r.shape) << " epsilon " << r.epsilon;
  EXPECT_GT(r.epsilon, 5 * 0.25);
}

TEST(ToleranceRule, BadFractionsAreRefused) {
  const std::vector<StrokePoint> p{{0, 0, 0}, {10, 0, 1}};
  RecognizerConfig c;
  c.tolerance_size_fraction = 0;
  EXPECT_THROW(recognize(p, c), InvalidInput);
  c = {};
  c.tolerance_pen_radii = -1;
  EXPECT_THROW(recognize(p, c), InvalidInput);
  c = {};
  c.tolerance_pen_radii = 0; // the size alone: allowed
  EXPECT_NO_THROW(recognize(p, c));
}

} // namespace
} // namespace penshape
