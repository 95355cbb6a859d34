// The arrow rules of the grouper added for issue 23 (b23), each with a drawing it decides and
// checked to decide: with the rule switched off, the drawing it refuses passes (GroupRules).
#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "group_test_support.hpp"
#include "penshape/core/group_recognize.hpp"
#include "recognize/group/group_classifier.hpp"
#include "recognize/group/group_plausibility.hpp"

namespace penshape {
namespace {

using recognize_detail::group_rules;
using recognize_detail::GroupRules;
using test::next_start;
using test::stroke_along;

class ArrowGroupRulesTest : public ::testing::Test {
 protected:
  void TearDown() override { group_rules() = GroupRules{}; }
};

// A shaft from (0, 0) to the tip (100, 0) and a head stroke, after the strokes `before`.
std::vector<StrokeInput> arrow_after(std::vector<StrokeInput> before) {
  const double t0 = before.empty() ? 0.0 : next_start(before);
  before.push_back(stroke_along({{0, 0}, {100, 0}}, t0));
  before.push_back(stroke_along({{70, -25}, {100, 0}, {70, 25}}, next_start(before)));
  return before;
}

// Whether the last two strokes are one arrow.
bool last_two_an_arrow(const std::vector<GroupedShape>& out, std::size_t strokes) {
  for (const GroupedShape& g : out) {
    if (g.strokes == std::vector<std::size_t>{strokes - 2, strokes - 1})
      return g.recognition.shape == ShapeClass::kArrow;
  }
  return false;
}

TEST_F(ArrowGroupRulesTest, AStrokeLeavingTheTipForwardMakesNoArrow) {
  // A leg that leaves the hip forward, 20 degrees off the shaft's line (a stick figure's body and
  // arms read as an arrow whose tip is the hip).
  const auto s = arrow_after({stroke_along({{100, 0}, {175, 27}}, 0.0)});
  EXPECT_FALSE(last_two_an_arrow(recognize_strokes(s), s.size()));
  group_rules().no_continued_tips = false;
  EXPECT_TRUE(last_two_an_arrow(recognize_strokes(s), s.size()));
}

TEST_F(ArrowGroupRulesTest, AnArrowMayPointAtABoxOrACircle) {
  // The tip touches a box's side, then a circle: both run across the shaft's line there.
  const auto box =
      arrow_after({stroke_along({{100, -60}, {200, -60}, {200, 60}, {100, 60}, {100, -60}}, 0.0)});
  EXPECT_TRUE(last_two_an_arrow(recognize_strokes(box), box.size()));
  test::Path circle;
  for (int k = 0; k <= 64; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 64.0;
    circle.push_back({140.0 - 40.0 * std::cos(a), 40.0 * std::sin(a)});
  }
  const auto round = arrow_after({stroke_along(circle, 0.0)});
  EXPECT_TRUE(last_two_an_arrow(recognize_strokes(round), round.size()));
}

TEST_F(ArrowGroupRulesTest, AnArrowHasNoMoreStrokesThanParts) {
  // A shaft in two pieces and a barb in each of two strokes: four strokes for three parts.
  std::vector<StrokeInput> s{stroke_along({{0, 0}, {50, 0}}, 0.0)};
  s.push_back(stroke_along({{50, 0}, {100, 0}}, next_start(s)));
  s.push_back(stroke_along({{70, -25}, {100, 0}}, next_start(s)));
  s.push_back(stroke_along({{100, 0}, {70, 25}}, next_start(s)));
  Recognition arrow;
  arrow.shape = ShapeClass::kArrow;
  arrow.epsilon = 15.0;
  EXPECT_NE(recognize_detail::group_implausibility(arrow, s, {}).find("parts"), std::string::npos);
  EXPECT_EQ(recognize_detail::group_implausibility(arrow, std::span(s).last(3), {}), "");
  group_rules().a_stroke_per_arrow_part = false;
  EXPECT_EQ(recognize_detail::group_implausibility(arrow, s, {}), "");
}

TEST_F(ArrowGroupRulesTest, NoStrokeOfAnArrowIsALoop) {
  // A half note: a ring as its head and a stem from its side.
  test::Path ring;
  for (int k = 0; k <= 64; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 64.0;
    ring.push_back({20.0 * std::cos(a), 15.0 * std::sin(a)});
  }
  const std::vector<StrokeInput> s{stroke_along(ring, 0.0),
                                   stroke_along({{20, 0}, {20, -100}}, 1.0)};
  Recognition arrow;
  arrow.shape = ShapeClass::kArrow;
  arrow.epsilon = 15.0;
  EXPECT_NE(recognize_detail::group_implausibility(arrow, s, {}).find("circle"), std::string::npos);
  group_rules().no_round_arrow_pieces = false;
  EXPECT_EQ(recognize_detail::group_implausibility(arrow, s, {}), "");
}

TEST_F(ArrowGroupRulesTest, ARefusedWinnerGivesWayToACertifiedArrow) {
  // Two strokes whose union's winner is an open polyline (never a group) while an arrow, also
  // certified and plausible, ranks below it.
  const std::vector<StrokeInput> s = arrow_after({});
  recognize_detail::UnionRecognition u;
  u.recognition.shape = ShapeClass::kPolyline;
  u.recognition.epsilon = 15.0;
  Candidate arrow;
  arrow.shape = ShapeClass::kArrow;
  arrow.params.vertices = {{0, 0}, {100, 0}, {70, -25}, {70, 25}};
  arrow.clean = {{0, 0}, {100, 0}, {70, -25}, {100, 0}, {70, 25}};
  arrow.certificate.certified = true;
  arrow.certificate.bound = 1.0;
  Candidate refused = arrow;
  refused.rejected = "not plausible";
  u.recognition.alternatives = {refused, arrow};
  recognize_detail::UnionRecognition kept = u;
  ASSERT_TRUE(recognize_detail::keep_union(kept, s, {}, {}));
  EXPECT_EQ(kept.recognition.shape, ShapeClass::kArrow);
  ASSERT_FALSE(kept.recognition.alternatives.empty());
  EXPECT_EQ(kept.recognition.alternatives.front().shape, ShapeClass::kPolyline);
  group_rules().arrow_when_refused = false;
  EXPECT_FALSE(recognize_detail::keep_union(u, s, {}, {}));
}

} // namespace
} // namespace penshape
