// The arrow rules of ArrowRules (fit_arrow.hpp) for arrows drawn as a shaft stroke and a head
// stroke: each with a drawing it lets through, checked to decide (with the rule off, the drawing
// is no arrow), and the certificate checked independently (group_test_support.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "group_test_support.hpp"
#include "penshape/core/group_recognize.hpp"
#include "recognize/arrow/fit_arrow.hpp"
#include "recognize/group/group_plausibility.hpp"

namespace penshape {
namespace {

using recognize_detail::arrow_rules;
using recognize_detail::ArrowRules;
using test::next_start;
using test::stroke_along;

class ArrowRulesTest : public ::testing::Test {
 protected:
  void TearDown() override {
    arrow_rules() = ArrowRules{};
    recognize_detail::group_rules() = recognize_detail::GroupRules{};
  }
};

// A head at `tip` pointing along +x: barbs of the given lengths leaving the shaft's line at 35
// degrees, drawn from the upper barb's end through the tip to the lower one's.
test::Path head(PointD tip, double upper, double lower) {
  const double c = std::cos(35.0 * std::numbers::pi / 180.0);
  const double s = std::sin(35.0 * std::numbers::pi / 180.0);
  return {{tip.x - upper * c, tip.y - upper * s}, tip, {tip.x - lower * c, tip.y + lower * s}};
}

// Whether the strokes come out as one arrow of both strokes, certified on their union.
bool one_arrow(const std::vector<StrokeInput>& s) {
  const auto out = recognize_strokes(s);
  if (out.size() != 1 || out[0].recognition.shape != ShapeClass::kArrow) return false;
  const Recognition& r = out[0].recognition;
  const double h =
      test::union_hausdorff(test::paths_of(s, {0, 1}), test::clean_paths(r), r.epsilon / 20.0);
  EXPECT_LE(h, r.certificate.bound + 1e-6);
  return r.certificate.certified;
}

// A long lower barb reaches farther from the tip than the shaft's tail: the drawing's farthest
// points are no tail and tip, and only the strokes themselves tell the head from the shaft.
TEST_F(ArrowRulesTest, AHeadStrokeAndAShaftStrokeAreSeededFromTheStrokes) {
  std::vector<StrokeInput> s{stroke_along({{0, 0}, {100, 0}}, 0.0)};
  s.push_back(stroke_along(head({100, 0}, 25.0, 105.0), next_start(s)));
  EXPECT_TRUE(one_arrow(s));
  arrow_rules().seed_from_strokes = false;
  EXPECT_FALSE(one_arrow(s));
}

// The same with the head drawn first and the shaft stopping a little short of the tip.
TEST_F(ArrowRulesTest, TheHeadMayComeFirstAndTheShaftStopShort) {
  std::vector<StrokeInput> s{stroke_along(head({100, 0}, 25.0, 105.0), 0.0)};
  s.push_back(stroke_along({{0, 0}, {96, 0}}, next_start(s)));
  EXPECT_TRUE(one_arrow(s));
  arrow_rules().seed_from_strokes = false;
  EXPECT_FALSE(one_arrow(s));
}

// A head drawn apart may be large beside its shaft (barbs up to kMaxSeparateHeadBarb shafts).
TEST_F(ArrowRulesTest, AHeadDrawnApartMayHaveBarbsLongerThanTheShaft) {
  std::vector<StrokeInput> s{stroke_along({{0, 0}, {100, 0}}, 0.0)};
  s.push_back(stroke_along(head({100, 0}, 40.0, 150.0), next_start(s)));
  EXPECT_TRUE(one_arrow(s));
  arrow_rules().max_apart_barb = 1.0;
  EXPECT_FALSE(one_arrow(s));
}

// A head far bigger than its shaft is a chevron beside a dash, not an arrow.
TEST_F(ArrowRulesTest, ABarbOfMoreThanTwoShaftsIsNoArrow) {
  std::vector<StrokeInput> s{stroke_along({{0, 0}, {60, 0}}, 0.0)};
  s.push_back(stroke_along(head({60, 0}, 140.0, 140.0), next_start(s)));
  EXPECT_FALSE(one_arrow(s));
  arrow_rules().max_apart_barb = 3.0;
  EXPECT_TRUE(one_arrow(s));
}

// Grouped as one arrow (recognize_strokes: the grouper's touch test included), certified on the
// union of both strokes; its shaft's end (absent: the shaft runs to the tip).
std::optional<PointD> gapped_arrow(const std::vector<StrokeInput>& s) {
  if (!one_arrow(s)) return std::nullopt;
  const Recognition r = recognize_strokes(s)[0].recognition;
  return r.params.shaft_end ? r.params.shaft_end : std::optional<PointD>{PointD{-1e9, -1e9}};
}

// A head at (100, 0) with barbs 50 long at 35 degrees, and a shaft stroke from `tail` to `end`:
// with the shaft ending at (55, 0) the gap is 45 (0.9 barbs), above what the arrow whose shaft
// runs to the tip covers within epsilon (about 14), and the strokes do not touch.
std::vector<StrokeInput> shaft_short_of(PointD tail, PointD end) {
  std::vector<StrokeInput> s{stroke_along({tail, end}, 0.0)};
  s.push_back(stroke_along(head({100, 0}, 50.0, 50.0), next_start(s)));
  return s;
}

// A shaft drawn in its own stroke that stops short of its head's tip, aimed at it: an arrow of
// two pieces (ShapeParams::shaft_end), certified on both strokes.
TEST_F(ArrowRulesTest, AShaftMayStopShortOfTheTip) {
  const auto s = shaft_short_of({0, 0}, {55, 0});
  const auto end = gapped_arrow(s);
  ASSERT_TRUE(end.has_value());
  EXPECT_LT(std::hypot(end->x - 55.0, end->y), 8.0);
  arrow_rules().gapped_shafts = false;
  EXPECT_FALSE(gapped_arrow(s).has_value());
}

// The strokes of such an arrow do not touch: the grouper tries them together only within
// GroupRules::apart_join epsilons more than touching.
TEST_F(ArrowRulesTest, TwoStrokesApartAreTriedAsAnArrowWithAGap) {
  const auto s = shaft_short_of({0, 0}, {55, 0});
  EXPECT_TRUE(gapped_arrow(s).has_value());
  recognize_detail::group_rules().apart_join = 0.0;
  EXPECT_FALSE(gapped_arrow(s).has_value());
}

// The gap is at most kMaxGapBarb mean barbs (0.9 here).
TEST_F(ArrowRulesTest, TheGapIsAtMostABarb) {
  const auto s = shaft_short_of({0, 0}, {55, 0});
  EXPECT_TRUE(gapped_arrow(s).has_value());
  arrow_rules().max_gap_barb = 0.7;
  EXPECT_FALSE(gapped_arrow(s).has_value());
}

// The shaft is aimed at the tip: one 20 degrees off, whose line passes 15 from it, is a stroke
// beside a head, not its shaft.
TEST_F(ArrowRulesTest, AShaftThatStopsShortIsAimedAtTheTip) {
  const auto s = shaft_short_of({0, -25}, {55, -2});
  EXPECT_FALSE(gapped_arrow(s).has_value());
  arrow_rules().max_gap_aim = 30.0 * std::numbers::pi / 180.0;
  EXPECT_TRUE(gapped_arrow(s).has_value());
}

// A shaft that runs to the tip keeps today's one-piece arrow (no shaft_end): the gapped reading
// only rescues a drawing the joined arrow does not certify.
TEST_F(ArrowRulesTest, AShaftToTheTipHasNoShaftEnd) {
  std::vector<StrokeInput> s{stroke_along({{0, 0}, {100, 0}}, 0.0)};
  s.push_back(stroke_along(head({100, 0}, 30.0, 30.0), next_start(s)));
  const auto end = gapped_arrow(s);
  ASSERT_TRUE(end.has_value());
  EXPECT_EQ(end->x, -1e9) << "a shaft_end " << end->x << ", " << end->y;
}

// An arrow pointing along +x with its tip at the origin and its tail at (-150, 0); its head V
// drawn as one stroke, and `shaft` as the other: whether the head counts as drawn apart.
bool apart_with(const test::Path& shaft) {
  recognize_detail::Fit f;
  f.shape = ShapeClass::kArrow;
  f.params.vertices = {{-150, 0}, {0, 0}, {-100, -60}, {-100, 60}};
  const recognize_detail::UnionStroke u =
      recognize_detail::prepare_union({{{-100, -60}, {0, 0}, {-100, 60}}, shaft}, 0.0);
  return recognize_detail::head_drawn_apart(f, u, 30.0);
}

// A stroke across the shaft (the bar of an A) lies within a loose epsilon of it near the tail but
// draws no shaft: a shaft stroke runs along at least kMinShaftSpan of its shaft.
TEST_F(ArrowRulesTest, AStrokeAcrossTheShaftIsNoShaft) {
  EXPECT_TRUE(apart_with({{-150, 0}, {-20, 0}}));
  EXPECT_FALSE(apart_with({{-150, -20}, {-150, 20}}));
  arrow_rules().min_shaft_span = 0.0;
  EXPECT_TRUE(apart_with({{-150, -20}, {-150, 20}}));
}

} // namespace
} // namespace penshape

namespace penshape {
namespace {

// Whether the strokes come out as one arrow of all of them, certified on their union (checked
// independently); `got` receives it.
bool one_arrow_of_all(const std::vector<StrokeInput>& s, Recognition* got = nullptr) {
  const auto out = recognize_strokes(s);
  if (out.size() != 1 || out[0].recognition.shape != ShapeClass::kArrow) return false;
  const Recognition& r = out[0].recognition;
  std::vector<std::size_t> all;
  for (std::size_t i = 0; i < s.size(); ++i) all.push_back(i);
  const double h =
      test::union_hausdorff(test::paths_of(s, all), test::clean_paths(r), r.epsilon / 20.0);
  EXPECT_LE(h, r.certificate.bound + 1e-6);
  if (got != nullptr) *got = r;
  return r.certificate.certified;
}

// A head at `tip` whose shaft arrives along the unit vector `along`: barbs 30 long leaving the
// shaft's end at 30 degrees, drawn from one barb's end through the tip to the other's.
test::Path head_along(PointD tip, PointD along) {
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const PointD back{-along.x, -along.y};
  const PointD left{c * back.x - s * back.y, s * back.x + c * back.y};
  const PointD right{c * back.x + s * back.y, -s * back.x + c * back.y};
  return {{tip.x + 30 * left.x, tip.y + 30 * left.y},
          tip,
          {tip.x + 30 * right.x, tip.y + 30 * right.y}};
}

// The path followed by a head drawn on from the shaft's end: tip, one barb, back, the other.
test::Path shaft_then_head(test::Path shaft, const test::Path& head) {
  shaft.insert(shaft.end(), {head[0], head[1], head[2]});
  return shaft;
}

// An elbow arrow: 120 along +x, a right-angle turn, 90 up to the tip. Both barbs lie on one side
// of the chord tail -> tip, so the head is found only against the shaft's end piece: one stroke,
// and a shaft stroke then a V, are arrows with one bend at the corner; with heads sought against
// the chord only, neither is an arrow.
TEST_F(ArrowRulesTest, AnElbowArrowsHeadIsFoundAgainstItsShaftsEnd) {
  const PointD tail{0, 0}, corner{120, 0}, tip{120, 90};
  const test::Path head = head_along(tip, {0, 1});
  const std::vector<StrokeInput> one{stroke_along(shaft_then_head({tail, corner, tip}, head), 0)};
  std::vector<StrokeInput> two{stroke_along({tail, corner, tip}, 0.0)};
  two.push_back(stroke_along(head, next_start(two)));
  for (const auto& s : {one, two}) {
    Recognition r;
    ASSERT_TRUE(one_arrow_of_all(s, &r)) << s.size() << " strokes";
    ASSERT_EQ(r.params.shaft_bends.size(), 1u);
    EXPECT_LT(
        std::hypot(r.params.shaft_bends[0].x - corner.x, r.params.shaft_bends[0].y - corner.y),
        0.6 * r.epsilon);
    EXPECT_LT(std::hypot(r.params.vertices[1].x - tip.x, r.params.vertices[1].y - tip.y),
              0.6 * r.epsilon);
  }
  arrow_rules().heads_at_shaft_end = false;
  EXPECT_FALSE(one_arrow_of_all(one));
  EXPECT_FALSE(one_arrow_of_all(two));
}

// A shaft drawn as an arc of about 93 degrees reaches its tip 46 degrees off its chord: a curved
// arrow (its bulge to the arc's side) in one stroke and as a shaft then a V, found only against
// the shaft's end.
TEST_F(ArrowRulesTest, ACurvedArrowsHeadIsFoundAgainstItsShaftsEnd) {
  const test::Path shaft = test::arc_through({0, 0}, {140, 0}, 30.0);
  const PointD tip = shaft.back(), before = shaft[shaft.size() - 2];
  const double step = std::hypot(tip.x - before.x, tip.y - before.y);
  const test::Path head = head_along(tip, {(tip.x - before.x) / step, (tip.y - before.y) / step});
  const std::vector<StrokeInput> one{stroke_along(shaft_then_head(shaft, head), 0)};
  std::vector<StrokeInput> two{stroke_along(shaft, 0.0)};
  two.push_back(stroke_along(head, next_start(two)));
  for (const auto& s : {one, two}) {
    Recognition r;
    ASSERT_TRUE(one_arrow_of_all(s, &r)) << s.size() << " strokes";
    EXPECT_TRUE(r.params.shaft_bends.empty());
    EXPECT_NEAR(r.params.shaft_bulge, 30.0, 0.6 * r.epsilon);
  }
  arrow_rules().heads_at_shaft_end = false;
  EXPECT_FALSE(one_arrow_of_all(one));
  EXPECT_FALSE(one_arrow_of_all(two));
}

// A long shaft's small head: epsilon follows the whole arrow (about 12% of its length), so barbs
// of 7.5% of the shaft are shorter than epsilon and lie within half of it of the shaft's line.
// They are a head at half the scale (finer_head_scales), where the whole arrow certifies: drawn
// in two strokes and in one (the shaft, then a barb out and back, then the other), with a hand's
// slow wobble along the shaft. Off, neither is an arrow.
TEST_F(ArrowRulesTest, ALongShaftsSmallHeadIsFoundAtAFinerScale) {
  for (const double length : {300.0, 600.0}) {
    test::Path shaft;
    for (int k = 0; k <= 40; ++k) {
      const double x = length * k / 40.0;
      shaft.push_back({x, 0.004 * length * std::sin(2.0 * std::numbers::pi * x / length)});
    }
    const PointD tip = shaft.back();
    const test::Path v = head(tip, 0.075 * length, 0.075 * length);
    std::vector<StrokeInput> two{stroke_along(shaft, 0.0)};
    two.push_back(stroke_along(v, next_start(two)));
    test::Path drawn = shaft;
    for (const PointD p : {v[0], tip, v[2]}) drawn.push_back(p);
    const std::vector<StrokeInput> one{stroke_along(drawn, 0.0)};
    const std::vector<StrokeInput>* const drawings[] = {&two, &one};
    for (const std::vector<StrokeInput>* strokes : drawings) {
      arrow_rules().finer_head_scales = true;
      const auto out = recognize_strokes(*strokes);
      ASSERT_EQ(out.size(), 1u) << length;
      const Recognition& r = out[0].recognition;
      ASSERT_EQ(r.shape, ShapeClass::kArrow) << length << " in " << strokes->size();
      std::vector<std::size_t> all(strokes->size());
      for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
      const double h = test::union_hausdorff(test::paths_of(*strokes, all), test::clean_paths(r),
                                             r.epsilon / 20.0);
      EXPECT_LE(h, r.epsilon / 2.0) << length; // certified at the finer scale
      EXPECT_LT(std::hypot(r.params.vertices[1].x - tip.x, r.params.vertices[1].y - tip.y),
                0.02 * length);
      arrow_rules().finer_head_scales = false;
      for (const GroupedShape& g : recognize_strokes(*strokes)) {
        EXPECT_NE(g.recognition.shape, ShapeClass::kArrow) << length << " in " << strokes->size();
      }
    }
  }
}

// The finer scale names no head that is not there: a long line whose end hooks back once (a
// flick of the pen) or zigzags on one side is still no arrow.
TEST_F(ArrowRulesTest, ALongLinesHookIsNoHeadAtAFinerScale) {
  const double c = std::cos(35.0 * std::numbers::pi / 180.0);
  const double s = std::sin(35.0 * std::numbers::pi / 180.0);
  const test::Path hooked{{0, 0}, {400, 0}, {400 - 30 * c, -30 * s}};
  const test::Path one_sided{
      {0, 0}, {400, 0}, {400 - 30 * c, -30 * s}, {400, 0}, {400 - 20 * c, -20 * s}};
  for (const test::Path& p : {hooked, one_sided}) {
    const std::vector<StrokeInput> line{stroke_along(p, 0.0)};
    for (const GroupedShape& g : recognize_strokes(line)) {
      EXPECT_NE(g.recognition.shape, ShapeClass::kArrow);
      EXPECT_NE(g.recognition.shape, ShapeClass::kDoubleArrow);
    }
  }
}

} // namespace
} // namespace penshape
