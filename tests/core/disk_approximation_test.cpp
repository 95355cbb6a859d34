#include "penshape/core/disk_approximation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "penshape/core/deconstruct.hpp"

namespace penshape {
namespace {

TEST(DiskApproximation, BothInclusionsHoldExactly) {
  const Rational cases[][2] = {{Rational(9, 10), Rational(1)},
                               {Rational(1), Rational(101, 100)},
                               {Rational(0), Rational(3)},
                               {Rational(49, 8), Rational(25, 4)},
                               {Rational(999, 1000), Rational(1)}};
  for (const auto& c : cases) {
    const Ring ring = disk_approximation(c[0], c[1], 100000);
    EXPECT_TRUE(is_disk_approximation(ring, c[0], c[1])) << c[0] << " " << c[1];
    for (const auto& p : ring) EXPECT_EQ(p.x * p.x + p.y * p.y, c[1] * c[1]); // on ∂D_b
    EXPECT_GT(twice_signed_area(ring), 0);
  }
}

TEST(DiskApproximation, IndependentFloatingCheckOfTheInnerRadius) {
  // The distance of the origin to each edge, computed in doubles, must be >= a (minus rounding).
  const Rational a(97, 100);
  const Rational b(1);
  const Ring ring = disk_approximation(a, b, 100000);
  const std::size_t n = ring.size();
  double min_dist = 1e9;
  for (std::size_t i = 0; i < n; ++i) {
    const PointD p = to_double(ring[i]);
    const PointD q = to_double(ring[(i + 1) % n]);
    const double d = std::abs(p.x * q.y - p.y * q.x) / std::hypot(q.x - p.x, q.y - p.y);
    min_dist = std::min(min_dist, d);
  }
  EXPECT_GE(min_dist, 0.97 - 1e-12);
  EXPECT_LE(min_dist, 1.0);
}

TEST(DiskApproximation, SizeGrowsLikeSqrtOfRatio) {
  // z0 = ceil(b / sqrt(b² - a²)): for b/(b-a) = 10000 roughly sqrt(5000) ≈ 71.
  const std::size_t z = disk_approximation_z(Rational(9999, 10000), Rational(1));
  EXPECT_GE(z, 70U);
  EXPECT_LE(z, 72U);
  // Fewer vertices than needed must fail the inclusion check: drop every other vertex.
  Ring ring = disk_approximation(Rational(9999, 10000), Rational(1), 100000);
  Ring sparse;
  for (std::size_t i = 0; i < ring.size(); i += 2) sparse.push_back(ring[i]);
  EXPECT_FALSE(is_disk_approximation(sparse, Rational(9999, 10000), Rational(1)));
}

TEST(DiskApproximation, RejectsBadRadiiAndHugeSizes) {
  EXPECT_THROW(disk_approximation(Rational(1), Rational(1), 1000), InvalidInput);
  EXPECT_THROW(disk_approximation(Rational(-1), Rational(1), 1000), InvalidInput);
  try {
    (void)disk_approximation(Rational(999999, 1000000), Rational(1), 1000);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("limit of 1000"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace penshape
