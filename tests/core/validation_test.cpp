// validate_deconstruct_input and the polygon readers: errors that name the problem.
#include <gtest/gtest.h>

#include <string>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_io.hpp"

namespace penshape {
namespace {

const DeconstructParams kOk{1, Rational(1, 10), Rational(1, 80), EngineKind::kReference};

PolygonSet square(int x, int y, int s) {
  return {{{{{x, y}, {x + s, y}, {x + s, y + s}, {x, y + s}}, {}}}};
}

std::string message(const PolygonSet& q, const DeconstructParams& p = kOk,
                    const DeconstructLimits& limits = {}) {
  try {
    validate_deconstruct_input(q, p, limits);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(Validation, AcceptsValidRegions) {
  EXPECT_EQ(message(square(0, 0, 5)), "");
  PolygonSet with_hole = square(0, 0, 10);
  with_hole.polygons[0].holes.push_back({{2, 2}, {2, 8}, {8, 8}, {8, 2}});
  PolygonSet island = square(4, 4, 2);
  with_hole.polygons.push_back(island.polygons[0]); // inside the hole: allowed
  EXPECT_EQ(message(with_hole), "");
}

TEST(Validation, EmptyAndDegenerateRings) {
  EXPECT_TRUE(has(message(PolygonSet{}), "empty"));
  PolygonSet two{{{{{0, 0}, {1, 0}}, {}}}};
  EXPECT_TRUE(has(message(two), "polygon 0, outer ring has 2 vertices"));
  PolygonSet flat{{{{{0, 0}, {1, 0}, {2, 0}}, {}}}};
  EXPECT_TRUE(has(message(flat), "zero area")) << message(flat);
  PolygonSet repeated{{{{{0, 0}, {1, 0}, {1, 0}, {0, 1}}, {}}}};
  EXPECT_TRUE(has(message(repeated), "polygon 0, outer ring: vertex 2 repeats vertex 1"))
      << message(repeated);
}

TEST(Validation, SelfIntersectionNamesTheEdges) {
  PolygonSet bowtie{{{{{0, 0}, {4, 4}, {4, 0}, {0, 6}}, {}}}};
  const std::string m = message(bowtie);
  EXPECT_TRUE(has(m, "polygon 0, outer ring is self-intersecting")) << m;
  EXPECT_TRUE(has(m, "edge 0-1")) << m;
  EXPECT_TRUE(has(m, "edge 2-3")) << m;
  PolygonSet spike{{{{{0, 0}, {4, 0}, {2, 0}, {2, 3}}, {}}}};
  EXPECT_TRUE(has(message(spike), "self-intersecting")) << message(spike);
  PolygonSet touching{{{{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}, {}}}};
  EXPECT_TRUE(has(message(touching), "self-intersecting")) << message(touching);
}

// Fold-backs are checked only once the crossing sweep found a contact (validate_input.cpp); the
// message still names the fold-back, also when the sweep meets another contact first.
TEST(Validation, FoldBackIsNamedAsSuch) {
  PolygonSet spike{{{{{0, 0}, {4, 0}, {2, 0}, {2, 3}}, {}}}};
  EXPECT_TRUE(has(message(spike), "edge 0-1 from (0, 0) to (4, 0) and 1 fold back on each other"))
      << message(spike);
  // A spike at x = 10 and, left of it, a crossing that the sweep reaches first.
  PolygonSet both{{{{{0, 0}, {10, 0}, {6, 0}, {6, 5}, {-10, 5}, {-4, -4}, {-10, -4}}, {}}}};
  EXPECT_TRUE(has(message(both), "edge 0-1 from (0, 0) to (10, 0) and 1 fold back on each other"))
      << message(both);
}

TEST(Validation, HolesAndPolygons) {
  PolygonSet outside = square(0, 0, 4);
  outside.polygons[0].holes.push_back({{10, 10}, {10, 11}, {11, 11}, {11, 10}});
  EXPECT_TRUE(has(message(outside), "polygon 0, hole 0 lies outside its outer ring"));
  PolygonSet nested = square(0, 0, 10);
  nested.polygons[0].holes.push_back({{1, 1}, {1, 9}, {9, 9}, {9, 1}});
  nested.polygons[0].holes.push_back({{2, 2}, {2, 3}, {3, 3}, {3, 2}});
  EXPECT_TRUE(has(message(nested), "holes overlap")) << message(nested);
  PolygonSet crossing = square(0, 0, 4);
  crossing.polygons[0].holes.push_back({{1, 1}, {1, 5}, {3, 5}, {3, 1}});
  EXPECT_TRUE(has(message(crossing), "rings intersect")) << message(crossing);
  PolygonSet overlap = square(0, 0, 10);
  overlap.polygons.push_back(square(2, 2, 2).polygons[0]);
  EXPECT_TRUE(has(message(overlap), "polygon 1 overlaps polygon 0")) << message(overlap);
}

TEST(Validation, ExtremeScalesAreDecidedExactly) {
  // Coordinates far below and above the double filter's safe range still validate exactly.
  for (const Rational& scale :
       {Rational(parse_rational("1e-320")), Rational(parse_rational("1e300"))}) {
    PolygonSet sq = square(0, 0, 5);
    for (auto& v : sq.polygons[0].outer) {
      v.x *= scale;
      v.y *= scale;
    }
    EXPECT_EQ(message(sq), "");
    PolygonSet bowtie{{{{{0, 0}, {4 * scale, 4 * scale}, {4 * scale, 0}, {0, 6 * scale}}, {}}}};
    EXPECT_TRUE(has(message(bowtie), "self-intersecting"));
    PolygonSet flat{{{{{0, 0}, {scale, 0}, {2 * scale, 0}}, {}}}};
    EXPECT_TRUE(has(message(flat), "zero area"));
  }
}

TEST(Validation, CancelHookStopsTheCrossingSweep) {
  // A comb of horizontal teeth: every edge overlaps every other in x (the sweep's worst case).
  // Teeth from x = 0 to 100, joined by a spine from x = -1 to 0.
  const int teeth = 400;
  Ring ring;
  ring.push_back({-1, 0});
  for (int i = 0; i < teeth; ++i) {
    ring.push_back({100, 2 * i});
    ring.push_back({100, 2 * i + 1});
    ring.push_back({0, 2 * i + 1});
    if (i + 1 < teeth) ring.push_back({0, 2 * i + 2});
  }
  ring.push_back({-1, 2 * teeth - 1});
  const PolygonSet q{{{ring, {}}}};
  EXPECT_NO_THROW(validate_region(q));
  EXPECT_THROW(validate_region(q, 200'000, [] { return true; }), Cancelled);
  EXPECT_THROW(deconstruct(q, kOk, [] { return true; }), Cancelled);
}

TEST(Validation, Parameters) {
  const PolygonSet q = square(0, 0, 5);
  auto p = kOk;
  p.radius = 0;
  EXPECT_TRUE(has(message(q, p), "radius must be positive"));
  p = kOk;
  p.tolerance = -1;
  EXPECT_TRUE(has(message(q, p), "tolerance must be positive"));
  p = kOk;
  p.precision = 0;
  EXPECT_TRUE(has(message(q, p), "precision must be positive"));
  p = kOk;
  p.precision = p.tolerance;
  EXPECT_TRUE(has(message(q, p), "precision must be smaller than the tolerance"));
}

TEST(Validation, LimitsStateTheBound) {
  auto p = kOk;
  p.precision = Rational(1, 100'000'000);
  const std::string m = message(square(0, 0, 5), p);
  EXPECT_TRUE(has(m, "over the limit of 4096")) << m;
  const std::string v = message(square(0, 0, 5), kOk, {.max_input_vertices = 3});
  EXPECT_TRUE(has(v, "4 vertices, over the limit of 3")) << v;
  EXPECT_THROW(deconstruct(square(0, 0, 5), p), InvalidInput);
}

TEST(PolygonText, XyRingsNestIntoHolesAndIslands) {
  const PolygonSet q = read_xy(
      "# square with a hole and an island\n0 0\n10 0\n10 10\n0 10\n0 0\n\n2 2\n8 2\n8 8\n2 8\n\n"
      "4 4\n6 4\n6 6\n4 6\n");
  ASSERT_EQ(q.polygons.size(), 2U);
  EXPECT_EQ(q.polygons[0].outer.size(), 4U); // the closing repeat is dropped
  ASSERT_EQ(q.polygons[0].holes.size(), 1U);
  EXPECT_LT(twice_signed_area(q.polygons[0].holes[0]), 0); // holes clockwise
  EXPECT_EQ(area(q), Rational(100 - 36 + 4));
  EXPECT_NO_THROW(validate_region(q));
}

// Rings whose first points lie on each other's edges each count as inside the other: no ring
// is an outer one. Found by the file readers' fuzzer (an out-of-range index); now each ring
// stands alone, and validation says the region is invalid.
TEST(PolygonText, RingsInsideEachOtherAreReadAndRefusedByValidation) {
  const PolygonSet q = read_xy("0 0\n1.5 0\n1.5 12\n\n0 0\n1.5 0\n1.5 12\n0 12\n");
  ASSERT_EQ(q.polygons.size(), 2U);
  EXPECT_THROW(validate_region(q), InvalidInput);
}

TEST(PolygonText, NumbersAreExact) {
  EXPECT_EQ(parse_rational("0.1"), Rational(1, 10));
  EXPECT_EQ(parse_rational("-2.5e-3"), Rational(-1, 400));
  EXPECT_EQ(parse_rational("3/6"), Rational(1, 2));
  EXPECT_EQ(parse_rational("1E2"), Rational(100));
  for (const char* bad : {"", "nan", "inf", "1e999", "1/0", "1.2.3", "--1", "0x10"}) {
    EXPECT_THROW(parse_rational(bad), InvalidInput) << bad;
  }
}

TEST(PolygonText, ErrorsNameTheLine) {
  try {
    read_xy("# c\n0 0\n1 0\n1 1 1\n");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line, 4U);
    EXPECT_TRUE(has(e.what(), "line 4")) << e.what();
  }
  EXPECT_THROW(read_xy("# only comments\n"), ParseError);
  try {
    read_wkt("POLYGON ((0 0, 1 0,\n 1 x, 0 0))");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line, 2U) << e.what();
  }
  EXPECT_THROW(read_wkt("POLYGON ((0 0, 1 0, 1 1, 0 0)"), ParseError);
  EXPECT_THROW(read_wkt("LINESTRING (0 0, 1 1)"), ParseError);
  EXPECT_THROW(read_wkt("POLYGON Z ((0 0 0, 1 0 0, 1 1 0, 0 0 0))"), ParseError);
}

TEST(PolygonText, WktRoundTripsExactly) {
  const PolygonSet q = read_wkt(
      "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 8, 8 8, 8 2, 2 2)), "
      "((20 0, 21.125 0, 21 1/3, 20 0)))");
  ASSERT_EQ(q.polygons.size(), 2U);
  EXPECT_EQ(q.polygons[0].holes.size(), 1U);
  EXPECT_EQ(q.polygons[1].outer[1].x, Rational(169, 8));
  const PolygonSet again = read_polygon_text(to_wkt(q));
  ASSERT_EQ(again.polygons.size(), 2U);
  EXPECT_EQ(again.polygons[0].outer, q.polygons[0].outer);
  EXPECT_EQ(again.polygons[1].outer, q.polygons[1].outer);
  EXPECT_EQ(area(again), area(q));
}

} // namespace
} // namespace penshape
