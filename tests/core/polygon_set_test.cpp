#include "penshape/core/polygon_set.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace penshape {
namespace {

Ring square(double x0, double y0, double side) {
  return {exact(PointD{x0, y0}), exact(PointD{x0 + side, y0}), exact(PointD{x0 + side, y0 + side}),
          exact(PointD{x0, y0 + side})};
}

TEST(PolygonSet, DoublesConvertExactly) {
  // 0.1 is not 1/10 in binary; the exact conversion must keep the binary value, not round it.
  const Rational r = exact(0.1);
  EXPECT_NE(r, Rational(1, 10));
  EXPECT_EQ(r, Rational(3602879701896397, 36028797018963968));
  EXPECT_EQ(to_double(r), 0.1);
  EXPECT_EQ(exact(-2.5), Rational(-5, 2));
  Rational tiny = exact(std::numeric_limits<double>::denorm_min());
  mpq_mul_2exp(tiny.get_mpq_t(), tiny.get_mpq_t(), 1074);
  EXPECT_EQ(tiny, Rational(1));
}

TEST(PolygonSet, AreaSubtractsHoles) {
  PolygonSet set;
  set.polygons.push_back({square(0, 0, 10), {square(2, 2, 3)}});
  set.polygons.push_back({square(20, 0, 1), {}});
  normalize_orientation(set);
  EXPECT_EQ(area(set), Rational(100 - 9 + 1));
  EXPECT_EQ(set.vertex_count(), 12U);
}

TEST(PolygonSet, NormalizeOrientation) {
  Ring cw = square(0, 0, 1);
  std::reverse(cw.begin(), cw.end());
  PolygonSet set;
  set.polygons.push_back({cw, {square(0.25, 0.25, 0.5)}});
  normalize_orientation(set);
  EXPECT_GT(sgn(twice_signed_area(set.polygons[0].outer)), 0);
  EXPECT_LT(sgn(twice_signed_area(set.polygons[0].holes[0])), 0);
  EXPECT_EQ(twice_signed_area(set.polygons[0].holes[0]), Rational(-1, 2));
}

TEST(PolygonSet, EmptySet) {
  const PolygonSet set;
  EXPECT_TRUE(set.empty());
  EXPECT_EQ(area(set), 0);
  EXPECT_EQ(set.vertex_count(), 0U);
}

} // namespace
} // namespace penshape
