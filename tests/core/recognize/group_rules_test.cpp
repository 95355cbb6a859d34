// The grouping rules of GroupRules (group_plausibility.hpp), each with a drawing it refuses and
// one it keeps, and each checked to decide: with the rule switched off, the refused drawing
// passes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "group_test_support.hpp"
#include "penshape/core/group_recognize.hpp"
#include "recognize/group/group_classifier.hpp"
#include "recognize/group/group_plausibility.hpp"

namespace penshape {
namespace {

using recognize_detail::group_implausibility;
using recognize_detail::group_rules;
using recognize_detail::GroupRules;

// Restores the rules whatever a test switched off.
class GroupRulesTest : public ::testing::Test {
 protected:
  void TearDown() override { group_rules() = GroupRules{}; }
};

using test::next_start;
using test::stroke_along;

// A recognition of `shape` whose clean path is `outline` (epsilon 15, no pen): what
// group_implausibility is asked about once a union certifies.
Recognition answer(ShapeClass shape, const test::Path& outline) {
  Recognition r;
  r.shape = shape;
  r.clean = outline;
  r.epsilon = 15.0;
  return r;
}

// The bowl of a D: half an ellipse from (0, 0) through (70, 60) to (0, 120).
test::Path bowl() {
  test::Path p;
  for (int k = 0; k <= 40; ++k) {
    const double t = -std::numbers::pi / 2 + std::numbers::pi * k / 40.0;
    p.push_back({70.0 * std::cos(t), 60.0 + 60.0 * std::sin(t)});
  }
  return p;
}

TEST_F(GroupRulesTest, AnOpenPolylineInPiecesStaysApart) {
  std::vector<StrokeInput> s{stroke_along({{0, 0}, {0, 100}}, 0.0)};
  s.push_back(stroke_along({{2, 101}, {100, 100}}, next_start(s)));
  const auto out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kSegment);
  EXPECT_EQ(out[1].recognition.shape, ShapeClass::kSegment);
  group_rules().no_open_polylines = false;
  const auto off = recognize_strokes(s);
  ASSERT_EQ(off.size(), 1u);
  EXPECT_EQ(off[0].recognition.shape, ShapeClass::kPolyline);
}

TEST_F(GroupRulesTest, ATriangleInThreeSidesStillGroups) {
  // Each side alone stays apart until the last closes the outline (the pause is between strokes:
  // the first side joins though it was drawn more than the pause window before the last).
  std::vector<StrokeInput> s{stroke_along({{0, 100}, {60, 0}}, 0.0)};
  s.push_back(stroke_along({{60, 0}, {120, 100}}, next_start(s) + 1.5));
  s.push_back(stroke_along({{120, 100}, {0, 100}}, next_start(s) + 1.5));
  const auto out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kTriangle);
}

TEST_F(GroupRulesTest, TheBowlOfADIsNoPairOfSides) {
  const std::vector<StrokeInput> s{stroke_along({{0, 0}, {0, 120}}, 0.0),
                                   stroke_along(bowl(), 1.0)};
  // The quadrilateral a loose band lets through: two of its corners lie on the bowl.
  const Recognition quad =
      answer(ShapeClass::kQuadrilateral, {{0, 0}, {55, 15}, {55, 105}, {0, 120}, {0, 0}});
  EXPECT_NE(group_implausibility(quad, s, {}).find("curve"), std::string::npos);
  group_rules().no_curved_sides = false;
  EXPECT_EQ(group_implausibility(quad, s, {}), "");
}

// A regular hexagon of circumradius 100, its corners turned by `degrees` about its centre.
test::Path hexagon(double degrees) {
  test::Path p;
  for (int k = 0; k <= 6; ++k) {
    const double a = (60.0 * k + degrees) * std::numbers::pi / 180.0;
    p.push_back({100.0 * std::cos(a), 100.0 * std::sin(a)});
  }
  return p;
}

TEST_F(GroupRulesTest, AModelsCornersNeedNotSitOnTheDrawnTurns) {
  // A hexagon in two strokes of three sides; the answer's corners lie 18 units along the sides
  // from the drawn ones (epsilon 15; the outline stays within 11 of the strokes), as a tidied
  // regular polygon's may: a model corner (equal sides, right angles) reaches
  // epsilon / sin(turn / 2) = 30 along the strokes for their turn.
  const test::Path drawn = hexagon(0.0);
  const std::vector<StrokeInput> s{stroke_along({drawn[0], drawn[1], drawn[2], drawn[3]}, 0.0),
                                   stroke_along({drawn[3], drawn[4], drawn[5], drawn[6]}, 1.0)};
  const test::Path moved = hexagon(12.0);
  EXPECT_EQ(group_implausibility(answer(ShapeClass::kRegularPolygon, moved), s, {}), "");
  // A fitted polygon's corners are placed where the strokes turn: so far off, one is a curve.
  EXPECT_NE(group_implausibility(answer(ShapeClass::kPolygon, moved), s, {}).find("curve"),
            std::string::npos);
  EXPECT_EQ(group_implausibility(answer(ShapeClass::kPolygon, drawn), s, {}), "");
  // A D's bowl turns as little near a model corner as anywhere: the outline of
  // TheBowlOfADIsNoPairOfSides, taken for a model's, is still no pair of sides.
  const std::vector<StrokeInput> d{stroke_along({{0, 0}, {0, 120}}, 0.0),
                                   stroke_along(bowl(), 1.0)};
  const Recognition model =
      answer(ShapeClass::kRectangle, {{0, 0}, {55, 15}, {55, 105}, {0, 120}, {0, 0}});
  EXPECT_NE(group_implausibility(model, d, {}).find("curve"), std::string::npos);
}

// A union read as a `winner` with `outline` among its alternatives, certified (epsilon 15).
recognize_detail::UnionRecognition union_of(ShapeClass winner, const test::Path& clean,
                                            ShapeClass alternative, const test::Path& outline) {
  recognize_detail::UnionRecognition u;
  u.recognition = answer(winner, clean);
  u.recognition.certificate = {true, 10.0, 15.0, 0.0, 1.0, "path"};
  u.recognition.alternatives.push_back(
      {alternative, {}, outline, {true, 12.0, 15.0, 0.0, 1.0, "path"}, {}, 5.0});
  return u;
}

TEST_F(GroupRulesTest, ARoundWinnerOfStraightPiecesGivesWayToTheOutline) {
  // A hexagon in two strokes of three sides, its union read as a circle (a hand's lumps can make
  // a circle's band the tighter): a round shape with straight pieces is refused, and the union's
  // certified hexagon is kept instead, the circle first among its alternatives.
  const test::Path drawn = hexagon(0.0);
  const std::vector<StrokeInput> s{stroke_along({drawn[0], drawn[1], drawn[2], drawn[3]}, 0.0),
                                   stroke_along({drawn[3], drawn[4], drawn[5], drawn[6]}, 1.0)};
  test::Path circle;
  for (int k = 0; k <= 72; ++k) {
    const double a = k * std::numbers::pi / 36.0;
    circle.push_back({93.0 * std::cos(a), 93.0 * std::sin(a)});
  }
  auto u = union_of(ShapeClass::kCircle, circle, ShapeClass::kPolygon, drawn);
  EXPECT_NE(group_implausibility(u.recognition, s, {}).find("straight stroke"), std::string::npos);
  ASSERT_TRUE(recognize_detail::keep_union(u, s, {}, {}));
  EXPECT_EQ(u.recognition.shape, ShapeClass::kPolygon);
  ASSERT_FALSE(u.recognition.alternatives.empty());
  EXPECT_EQ(u.recognition.alternatives.front().shape, ShapeClass::kCircle);
  // The outline must pass the rules too: a D's bar and bowl read as an ellipse give way to no
  // quadrilateral with corners on the bowl.
  const std::vector<StrokeInput> d{stroke_along({{0, 0}, {0, 120}}, 0.0),
                                   stroke_along(bowl(), 1.0)};
  auto du = union_of(ShapeClass::kEllipse, bowl(), ShapeClass::kQuadrilateral,
                     {{0, 0}, {55, 15}, {55, 105}, {0, 120}, {0, 0}});
  EXPECT_FALSE(recognize_detail::keep_union(du, d, {}, {}));
  group_rules().outline_when_round_refused = false;
  auto off = union_of(ShapeClass::kCircle, circle, ShapeClass::kPolygon, drawn);
  EXPECT_FALSE(recognize_detail::keep_union(off, s, {}, {}));
}

TEST_F(GroupRulesTest, ARectangleAsTwoLsWithRoundedCornersKeepsItsCorners) {
  // Corners rounded with a radius of 6 (epsilon 15): the strokes still turn there.
  const std::vector<StrokeInput> s{
      stroke_along({{0, 80}, {0, 6}, {2, 2}, {6, 0}, {100, 0}}, 0.0),
      stroke_along({{100, 0}, {100, 74}, {98, 78}, {94, 80}, {0, 80}}, 1.0)};
  const Recognition rect =
      answer(ShapeClass::kRectangle, {{0, 0}, {100, 0}, {100, 80}, {0, 80}, {0, 0}});
  EXPECT_EQ(group_implausibility(rect, s, {}), "");
  const auto out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kRectangle);
}

TEST_F(GroupRulesTest, StrokesCrossingInTheirMiddlesAreNoOutline) {
  // Two sides of a triangle, then a stroke from its first end across the second side's middle.
  const std::vector<StrokeInput> s{stroke_along({{0, 100}, {50, 0}, {100, 100}}, 0.0),
                                   stroke_along({{0, 100}, {90, 40}}, 1.0)};
  const Recognition tri = answer(ShapeClass::kTriangle, {{0, 100}, {50, 0}, {100, 100}, {0, 100}});
  EXPECT_NE(group_implausibility(tri, s, {}).find("cross"), std::string::npos);
  group_rules().no_crossing_pieces = false;
  EXPECT_EQ(group_implausibility(tri, s, {}), "");
}

TEST_F(GroupRulesTest, TwoStrokesLeavingOnePointAreLimbsNotALine) {
  // Arms drawn from the body outward, one each way: no segment in pieces.
  const std::vector<StrokeInput> arms{stroke_along({{100, 0}, {0, 0}}, 0.0),
                                      stroke_along({{102, 0}, {200, 0}}, 1.0)};
  const Recognition line = answer(ShapeClass::kSegment, {{0, 0}, {200, 0}});
  EXPECT_NE(group_implausibility(line, arms, {}).find("limbs"), std::string::npos);
  // A line drawn on where the first piece stopped, or towards it, stays one segment.
  const std::vector<StrokeInput> on{stroke_along({{0, 0}, {100, 0}}, 0.0),
                                    stroke_along({{102, 0}, {200, 0}}, 1.0)};
  EXPECT_EQ(group_implausibility(line, on, {}), "");
  const std::vector<StrokeInput> towards{stroke_along({{0, 0}, {100, 0}}, 0.0),
                                         stroke_along({{200, 0}, {102, 0}}, 1.0)};
  EXPECT_EQ(group_implausibility(line, towards, {}), "");
  group_rules().no_limbs_as_a_line = false;
  EXPECT_EQ(group_implausibility(line, arms, {}), "");
}

TEST_F(GroupRulesTest, OvershootingCornersMayCross) {
  // The base overshoots both corners by 6 and crosses the sides near their ends.
  const std::vector<StrokeInput> s{stroke_along({{-3, 106}, {50, 0}, {103, 106}}, 0.0),
                                   stroke_along({{-6, 100}, {106, 100}}, 1.0)};
  const Recognition tri = answer(ShapeClass::kTriangle, {{0, 100}, {50, 0}, {100, 100}, {0, 100}});
  EXPECT_EQ(group_implausibility(tri, s, {}), "");
}

TEST_F(GroupRulesTest, AnArrowsStrokesMayNotCrossInBothMiddles) {
  // A shaft, a head, and a bar across the shaft's middle (as arms across a stick figure's body).
  const std::vector<StrokeInput> s{stroke_along({{0, 0}, {100, 0}}, 0.0),
                                   stroke_along({{70, -25}, {100, 0}, {70, 25}}, 1.0),
                                   stroke_along({{50, -20}, {50, 20}}, 2.0)};
  const Recognition arrow = answer(ShapeClass::kArrow, {{0, 0}, {100, 0}});
  EXPECT_NE(group_implausibility(arrow, s, {}).find("cross"), std::string::npos);
  // The head alone crosses the shaft at its tip: kept.
  EXPECT_EQ(group_implausibility(arrow, std::span(s).first(2), {}), "");
  group_rules().no_crossing_pieces = false;
  EXPECT_EQ(group_implausibility(arrow, s, {}), "");
}

} // namespace
} // namespace penshape
