// Exact offsets and insets by disk approximations, checked against closed-form areas (for a
// square S = [0, s]² and a centrally symmetric convex K with half-extents e_x, e_y:
// area(S ⊕ K) = s² + area(K) + 2·s·(e_x + e_y), and inset(S, K) = [e_x, s - e_x] × [e_y, s - e_y]).
#include "penshape/core/offset.hpp"

#include <gtest/gtest.h>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/disk_approximation.hpp"

namespace penshape {
namespace {

const Rational kSide(10);

PolygonSet square() { return {{{{{0, 0}, {kSide, 0}, {kSide, kSide}, {0, kSide}}, {}}}}; }

TEST(Offset, SquarePlusDiskApproximationHasTheClosedFormArea) {
  const Ring k = disk_approximation(Rational(9, 10), Rational(1), 4096);
  const PolygonSet grown = offset_by(square(), k);
  ASSERT_EQ(grown.polygons.size(), 1U);
  EXPECT_TRUE(grown.polygons[0].holes.empty());
  const Rational area_k = twice_signed_area(k) / 2;
  // D̄_{a,b} has vertices (±b, 0) and (0, ±b): both half-extents are b = 1.
  EXPECT_EQ(area(grown), kSide * kSide + area_k + 2 * kSide * 2);
  EXPECT_GT(twice_signed_area(grown.polygons[0].outer), 0); // counterclockwise
}

TEST(Offset, InsetOfSquareIsTheShrunkSquare) {
  const Ring k = disk_approximation(Rational(9, 10), Rational(1), 4096);
  const PolygonSet shrunk = inset_by(square(), k);
  ASSERT_EQ(shrunk.polygons.size(), 1U);
  EXPECT_EQ(area(shrunk), (kSide - 2) * (kSide - 2));
  // Insetting by more than half the side leaves nothing.
  const Ring big = disk_approximation(Rational(5), Rational(6), 4096);
  EXPECT_TRUE(inset_by(square(), big).empty());
}

TEST(Offset, OffsetClosesANarrowHole) {
  // A frame whose hole is 1 wide: growing by radius ~1 fills it.
  PolygonSet frame{{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{2, 2}, {2, 8}, {3, 8}, {3, 2}}}}}};
  const PolygonSet grown = offset_by(frame, disk_approximation(Rational(9, 10), Rational(1), 4096));
  ASSERT_EQ(grown.polygons.size(), 1U);
  EXPECT_TRUE(grown.polygons[0].holes.empty());
  EXPECT_TRUE(region_contains(grown, frame));
  EXPECT_FALSE(region_contains(frame, grown));
}

TEST(Offset, RejectsANonConvexSummand) {
  EXPECT_THROW(offset_by(square(), Ring{{1, 0}, {0, 1}, {-1, 0}, {0, Rational(1, 10)}, {0, -1}}),
               InvalidInput);
  EXPECT_THROW(offset_by(square(), Ring{{1, 1}, {2, 1}, {2, 2}}), InvalidInput); // origin outside
}

} // namespace
} // namespace penshape
