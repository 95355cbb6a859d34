// Groups that certify but are not drawn as their shape is drawn in pieces (group_plausibility):
// a T, a row of dashes; and an arrow whose head is drawn apart from its shaft. Each stroke
// keeps its own answer; no union of them snaps.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "group_test_support.hpp"
#include "penshape/core/group_recognize.hpp"
#include "recognize/group/group_plausibility.hpp"

namespace penshape {
namespace {

using test::next_start;
using test::stroke_along;

// Whether some answer covers several strokes and snaps.
bool merged(const std::vector<GroupedShape>& out) {
  for (const GroupedShape& g : out) {
    if (g.strokes.size() > 1 && g.recognition.shape != ShapeClass::kFreeform) return true;
  }
  return false;
}

TEST(GroupPlausibility, ATIsNoPolyline) {
  std::vector<StrokeInput> s{stroke_along({{0, 0}, {120, 0}}, 0.0)};
  s.push_back(stroke_along({{60, 0}, {60, 120}}, next_start(s)));
  const auto out = recognize_strokes(s);
  EXPECT_FALSE(merged(out));
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kSegment);
  EXPECT_EQ(out[1].recognition.shape, ShapeClass::kSegment);
}

TEST(GroupPlausibility, DashesFourMillimetresApartStaySeparate) {
  // 10 mm dashes, 4 mm gaps, a 1 mm pen: the row's epsilon grows with the row, a dash's does not.
  std::vector<StrokeInput> s;
  for (int k = 0; k < 4; ++k) {
    const double x = 14.0 * k;
    s.push_back(stroke_along({{x, 0}, {x + 10, 0.2}}, s.empty() ? 0.0 : next_start(s), 0.5));
  }
  const auto out = recognize_strokes(s);
  EXPECT_FALSE(merged(out));
  EXPECT_EQ(out.size(), 4u);
}

TEST(GroupPlausibility, AHeadDrawnApartMayBeAsLongAsTheShaft) {
  // The shaft, then the head in one stroke, its barbs 0.83 shafts long (people draw a head apart
  // large): an arrow, since the strokes tell the shaft from the head.
  std::vector<StrokeInput> s{stroke_along({{0, 0}, {100, 0}}, 0.0)};
  s.push_back(stroke_along({{30, -45}, {100, 0}, {30, 45}}, next_start(s)));
  const auto out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kArrow);
}

// A circle drawn round 300 degrees, then closed by a straight stroke across its 60-degree gap:
// the circle's own path over that stroke stands out from it by 8 units, well within epsilon / 2,
// and the arc goes on into it without a corner (flat_round_pieces). The straight stroke alone is
// a segment, no arc; with the rule off it keeps the union from being one circle.
TEST(GroupPlausibility, ACircleClosedByAShortStraightStrokeIsOneCircle) {
  constexpr double kRadius = 60.0;
  const auto at = [](double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    return PointD{kRadius * std::cos(a), kRadius * std::sin(a)};
  };
  test::Path arc;
  for (int d = 150; d >= -150; d -= 5) arc.push_back(at(d));
  std::vector<StrokeInput> s{stroke_along(arc, 0.0)};
  s.push_back(stroke_along({at(-150), at(150)}, next_start(s)));
  const auto out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].strokes.size(), 2u);
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kCircle) << to_string(out[0].recognition.shape);
  const Recognition& r = out[0].recognition;
  EXPECT_LE(test::union_hausdorff(test::paths_of(s, out[0].strokes), test::clean_paths(r),
                                  r.epsilon / 50),
            r.epsilon);
  recognize_detail::group_rules().flat_round_pieces = false;
  EXPECT_TRUE(recognize_strokes(s).size() != 1 ||
              recognize_strokes(s)[0].recognition.shape != ShapeClass::kCircle)
      << "the case no longer needs the rule";
  recognize_detail::group_rules() = recognize_detail::GroupRules{};
}

// A hexagon drawn in two strokes, the second closing it and running on along the first side
// (drawn round once and a side, as a hand closes a shape): it crosses the first stroke in the
// middle of that side, away from both strokes' ends, but runs on along it within epsilon / 2 to
// its end (overlaps_are_no_crossings): an overlap, no figure.
TEST(GroupPlausibility, AClosingStrokeThatOverlapsTheFirstIsNoCrossing) {
  const auto at = [](int k) {
    const double a = k * std::numbers::pi / 3.0;
    return PointD{60.0 * std::cos(a), 60.0 * std::sin(a)};
  };
  std::vector<StrokeInput> s{stroke_along({at(0), at(1), at(2), at(3)}, 0.0)};
  // Along the first side from 3 units outside to 3 units inside the hexagon.
  const PointD out{at(0).x * 1.05, at(0).y * 1.05};
  const PointD in{at(1).x * 0.95, at(1).y * 0.95};
  s.push_back(stroke_along({at(3), at(4), at(5), out, in}, next_start(s)));
  const auto out_shapes = recognize_strokes(s);
  ASSERT_EQ(out_shapes.size(), 1u);
  EXPECT_EQ(out_shapes[0].strokes.size(), 2u);
  const Recognition& r = out_shapes[0].recognition;
  EXPECT_TRUE(r.shape == ShapeClass::kRegularPolygon || r.shape == ShapeClass::kPolygon)
      << to_string(r.shape);
  EXPECT_EQ(r.params.vertices.size(), 6u);
  EXPECT_LE(test::union_hausdorff(test::paths_of(s, out_shapes[0].strokes), test::clean_paths(r),
                                  r.epsilon / 50),
            r.epsilon);
  recognize_detail::group_rules().overlaps_are_no_crossings = false;
  EXPECT_FALSE(merged(recognize_strokes(s))) << "the case no longer needs the rule";
  recognize_detail::group_rules() = recognize_detail::GroupRules{};
}

} // namespace
} // namespace penshape
