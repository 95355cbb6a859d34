#include "penshape/core/polygon_set.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

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

// to_double is the nearest double, checked against both neighbours with exact arithmetic, on
// grid coordinates (n * 2^-m, the fast path), numerators wider than a double, values below the
// normal range and non-dyadic rationals.
TEST(PolygonSet, ToDoubleIsTheNearestDouble) {
  std::mt19937_64 rng(12345);
  auto nearest = [](const Rational& v, double d) {
    const Rational gap = abs(v - exact(d));
    for (const double side : {-HUGE_VAL, HUGE_VAL}) {
      const double neighbour = std::nextafter(d, side);
      if (std::isfinite(neighbour) && abs(v - exact(neighbour)) < gap) return false;
    }
    return true;
  };
  for (int i = 0; i < 4000; ++i) {
    const int bits = 1 + static_cast<int>(rng() % 80); // up to 80-bit numerators
    mpz_class n = 0;
    for (int b = 0; b < bits; ++b) n = 2 * n + static_cast<long>(rng() % 2);
    if (rng() % 2 == 0) n = -n;
    Rational v(n);
    const unsigned k = static_cast<unsigned>(rng() % 1100); // past 1000: near the subnormals
    mpq_div_2exp(v.get_mpq_t(), v.get_mpq_t(), k);
    if (i % 4 == 3) v /= 3 + static_cast<long>(rng() % 1000) * 2; // not dyadic
    const double d = to_double(v);
    ASSERT_TRUE(nearest(v, d)) << v.get_str() << " -> " << d;
    if (bits <= 53 && k < 1000 && i % 4 != 3) {
      EXPECT_EQ(exact(d), v) << v.get_str();
    }
  }
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
