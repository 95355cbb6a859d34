// offset(P, r) with true arcs, checked independently: every sampled boundary point (along
// segments and along the arcs themselves) is at distance r from P up to the stated error, the
// curves chain into closed rings, and arcs sit on P's vertices.
#include "penshape/core/arc_offset.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_io.hpp"
#include "polygon_gen.hpp"
#include "support/hausdorff_check.hpp"
#include "test_data.hpp"

namespace penshape {
namespace {

struct Counts {
  std::size_t segments = 0;
  std::size_t arcs = 0;
};

// Distance from p to the region P (0 inside), independent of the code under test.
double distance_to_p(const test::RegionD& p, PointD x) { return test::distance_to_region(p, x); }

Counts check_ring(const CurveRing& ring, const test::RegionD& p, double r, double err) {
  Counts c;
  EXPECT_FALSE(ring.curves.empty());
  for (std::size_t i = 0; i < ring.curves.size(); ++i) {
    const BoundaryCurve& k = ring.curves[i];
    const BoundaryCurve& next = ring.curves[(i + 1) % ring.curves.size()];
    EXPECT_NEAR(k.end.x, next.start.x, 1e-12);
    EXPECT_NEAR(k.end.y, next.start.y, 1e-12);
    for (int s = 0; s <= 8; ++s) {
      const double t = s / 8.0;
      PointD x;
      if (k.kind == BoundaryCurve::Kind::kSegment) {
        ++c.segments;
        x = {k.start.x + t * (k.end.x - k.start.x), k.start.y + t * (k.end.y - k.start.y)};
      } else {
        ++c.arcs;
        EXPECT_DOUBLE_EQ(k.radius, r);
        const double a0 = std::atan2(k.start.y - k.center.y, k.start.x - k.center.x);
        double a1 = std::atan2(k.end.y - k.center.y, k.end.x - k.center.x);
        while (a1 < a0) a1 += 2 * std::numbers::pi; // counterclockwise
        const double a = a0 + t * (a1 - a0);
        x = {k.center.x + r * std::cos(a), k.center.y + r * std::sin(a)};
      }
      EXPECT_NEAR(distance_to_p(p, x), r, err) << "curve " << i << " t " << t;
    }
  }
  return c;
}

TEST(ArcOffset, SquareHasFourSegmentsAndFourArcs) {
  const PolygonSet square{{{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}}}};
  const CurvedRegion region = offset_with_arcs(square, 1.0);
  ASSERT_EQ(region.polygons.size(), 1U);
  const auto& outer = region.polygons[0].outer;
  const Counts c = check_ring(outer, test::to_region_d(square), 1.0, region.max_error);
  EXPECT_EQ(c.arcs, 4U * 9);
  EXPECT_EQ(c.segments, 4U * 9);
  for (const auto& k : outer.curves) {
    if (k.kind == BoundaryCurve::Kind::kArc) {
      EXPECT_TRUE((k.center.x == 0 || k.center.x == 4) && (k.center.y == 0 || k.center.y == 4));
    }
  }
}

// Simplification and the convex path return curves (zero-area rings): their offset is the
// stroke of the curve with round ends.
TEST(ArcOffset, ASegmentIsAStadium) {
  const PolygonSet segment{{{{{0, 0}, {6, 0}}, {}}}};
  const CurvedRegion region = offset_with_arcs(segment, 1.0);
  ASSERT_EQ(region.polygons.size(), 1U);
  EXPECT_TRUE(region.polygons[0].holes.empty());
  const Counts c =
      check_ring(region.polygons[0].outer, test::to_region_d(segment), 1.0, region.max_error);
  EXPECT_EQ(c.arcs, 2U * 9);
  EXPECT_EQ(c.segments, 2U * 9);
}

TEST(ArcOffset, APolylineWalkedThereAndBackIsItsStroke) {
  const PolygonSet polyline{{{{{0, 0}, {4, 0}, {4, 3}, {4, 0}}, {}}}};
  const CurvedRegion region = offset_with_arcs(polyline, 1.0);
  ASSERT_EQ(region.polygons.size(), 1U);
  EXPECT_TRUE(region.polygons[0].holes.empty());
  const Counts c =
      check_ring(region.polygons[0].outer, test::to_region_d(polyline), 1.0, region.max_error);
  EXPECT_EQ(c.arcs, 3U * 9); // both ends and the outside of the corner
}

TEST(ArcOffset, APointIsADiskAndCurvesSitBesideRegions) {
  const PolygonSet mixed{{{{{20, 20}}, {}}, {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}}}};
  const CurvedRegion region = offset_with_arcs(mixed, 1.0);
  ASSERT_EQ(region.polygons.size(), 2U);
  for (const auto& polygon : region.polygons) {
    check_ring(polygon.outer, test::to_region_d(mixed), 1.0, region.max_error);
  }
  const PolygonSet curve_with_hole{{{{{0, 0}, {6, 0}}, {{{1, 1}, {2, 1}, {2, 2}}}}}};
  EXPECT_THROW((void)offset_with_arcs(curve_with_hole, 1.0), InvalidInput);
}

TEST(ArcOffset, HoleShrinksWithSharpCorners) {
  PolygonSet frame{{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{2, 2}, {2, 8}, {8, 8}, {8, 2}}}}}};
  const CurvedRegion region = offset_with_arcs(frame, 1.0);
  ASSERT_EQ(region.polygons.size(), 1U);
  ASSERT_EQ(region.polygons[0].holes.size(), 1U);
  const auto p = test::to_region_d(frame);
  const Counts hole = check_ring(region.polygons[0].holes[0], p, 1.0, region.max_error);
  EXPECT_EQ(hole.arcs, 0U); // P's corners at the hole are reflex: no arcs there
  check_ring(region.polygons[0].outer, p, 1.0, region.max_error);
}

// The arc offset of a deconstruction's solution has arcs at its convex corners.
void expect_solution_offset_has_arcs(const PolygonSet& q) {
  const auto res = deconstruct(q, {1, Rational(1, 10), Rational(1, 80), EngineKind::kReference});
  ASSERT_EQ(res.answer, Answer::kYes);
  const CurvedRegion region = offset_with_arcs(res.solution, 1.0, 1e-4);
  ASSERT_FALSE(region.polygons.empty());
  const Counts c =
      check_ring(region.polygons[0].outer, test::to_region_d(res.solution), 1.0, region.max_error);
  EXPECT_GT(c.arcs, 0U);
}

TEST(ArcOffset, DemoSolutionOffset) {
  PENSHAPE_SHARED_OR_SKIP(file, "polygons/authors_demo_1_01_work2.txt");
  expect_solution_offset_has_arcs(read_xy(test::read_file(file)));
}

TEST(ArcOffset, GeneratedSolutionOffset) {
  // Q = a convex heptagon offset by r = 1 (chords on the arcs within 0.02): a YES at eps 0.1.
  expect_solution_offset_has_arcs(read_xy(gen::rounded_convex(3, 7, 12.0, 1.0, 0.02).q.text));
}

TEST(ArcOffset, BadInput) {
  const PolygonSet square{{{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}}}};
  EXPECT_THROW(offset_with_arcs(square, 0.0), InvalidInput);
  EXPECT_THROW(offset_with_arcs(square, std::nan("")), InvalidInput);
  EXPECT_THROW(offset_with_arcs(square, 1.0, -1.0), InvalidInput);
  EXPECT_THROW(offset_with_arcs(PolygonSet{}, 1.0), InvalidInput);
}

} // namespace
} // namespace penshape
