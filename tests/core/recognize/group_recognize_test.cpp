// Grouping, arrows and tidy-up on synthetic strokes (always run): every snap is checked against
// an independent brute-force Hausdorff distance to the union of the strokes.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <numbers>

#include "group_test_support.hpp"
#include "penshape/core/group_recognize.hpp"
#include "penshape/core/verify.hpp"

namespace penshape {
namespace {

using test::Path;

// A straight stroke from a to b with a gentle deterministic wobble of `wobble` px, starting at
// time t0 (one sample per 4 px, 10 ms apart).
std::vector<StrokePoint> line(PointD a, PointD b, double t0, double wobble = 1.0) {
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  const int n = std::max(3, static_cast<int>(len / 4));
  const PointD nrm{-(b.y - a.y) / len, (b.x - a.x) / len};
  std::vector<StrokePoint> out;
  for (int k = 0; k <= n; ++k) {
    const double f = static_cast<double>(k) / n;
    const double w = wobble * std::sin(7.0 * f);
    out.push_back(
        {a.x + f * (b.x - a.x) + w * nrm.x, a.y + f * (b.y - a.y) + w * nrm.y, t0 + 0.01 * k});
  }
  return out;
}

// Several straight pieces drawn as one stroke.
std::vector<StrokePoint> polyline(const std::vector<PointD>& v, double t0) {
  std::vector<StrokePoint> out;
  for (std::size_t i = 0; i + 1 < v.size(); ++i) {
    auto piece = line(v[i], v[i + 1], out.empty() ? t0 : out.back().t + 0.01);
    if (!out.empty()) piece.erase(piece.begin());
    out.insert(out.end(), piece.begin(), piece.end());
  }
  return out;
}

StrokeInput input(std::vector<StrokePoint> s) {
  StrokeInput in;
  in.samples = std::move(s);
  return in;
}

double end_time(const std::vector<StrokeInput>& s) { return s.back().samples.back().t; }

// The four sides of the rectangle (x0, y0)-(x1, y1), drawn one after the other with pauses.
std::vector<StrokeInput> four_sides(double pause = 0.3) {
  const std::vector<PointD> c{{0, 0}, {200, 0}, {200, 120}, {0, 120}};
  std::vector<StrokeInput> out;
  for (std::size_t i = 0; i < 4; ++i) {
    const double t0 = out.empty() ? 0.0 : end_time(out) + pause;
    // Side 2 drawn backwards; small overshoot and gap at the corners.
    if (i == 2) {
      out.push_back(input(line({c[3].x - 2, c[3].y}, {c[2].x + 1, c[2].y}, t0)));
    } else {
      out.push_back(input(line(c[i], c[(i + 1) % 4], t0)));
    }
  }
  return out;
}

void expect_independently_certified(const GroupedShape& g, const std::vector<StrokeInput>& s) {
  const Recognition& r = g.recognition;
  ASSERT_TRUE(r.certificate.certified);
  const double h =
      test::union_hausdorff(test::paths_of(s, g.strokes), test::clean_paths(r), r.epsilon / 50);
  // The brute force samples with step eps/50: it may miss up to half a step.
  EXPECT_LE(h, r.epsilon + r.epsilon / 100) << to_string(r.shape);
  EXPECT_LE(h, r.certificate.bound + r.epsilon / 100)
      << "the certified bound is not an upper bound";
}

TEST(GroupRecognize, RectangleFromFourSidesIsOneCertifiedRectangle) {
  const std::vector<StrokeInput> s = four_sides();
  const std::vector<GroupedShape> out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].strokes, (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kRectangle);
  expect_independently_certified(out[0], s);
}

TEST(GroupRecognize, FourthSideSupersedesTheThreeSideShape) {
  const std::vector<StrokeInput> s = four_sides();
  StrokeGrouper g;
  // An open polyline in pieces is no group: the three sides stand alone until the fourth.
  std::vector<std::size_t> sides;
  for (std::size_t i = 0; i < 3; ++i) {
    const GroupUpdate u = g.add(s[i]);
    EXPECT_EQ(u.shape.strokes, (std::vector<std::size_t>{i}));
    EXPECT_EQ(u.shape.recognition.shape, ShapeClass::kSegment);
    sides.push_back(u.shape.id);
  }
  const GroupUpdate last = g.add(s[3]);
  EXPECT_EQ(last.shape.recognition.shape, ShapeClass::kRectangle);
  std::vector<std::size_t> superseded = last.superseded;
  std::sort(superseded.begin(), superseded.end());
  EXPECT_EQ(superseded, sides);
  EXPECT_EQ(last.replaced_strokes, (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(g.shapes().size(), 1u);
}

TEST(GroupRecognize, ReorderedPiecesStillGroup) {
  std::vector<StrokeInput> s = four_sides();
  std::swap(s[0], s[2]);
  std::swap(s[1], s[3]);
  double t = 0;
  for (StrokeInput& st : s) { // re-time in the new order
    const double shift = t - st.samples.front().t;
    for (StrokePoint& p : st.samples) p.t += shift;
    t = st.samples.back().t + 0.4;
  }
  const std::vector<GroupedShape> out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kRectangle);
  expect_independently_certified(out[0], s);
}

TEST(GroupRecognize, LongPauseStartsANewDrawing) {
  const std::vector<GroupedShape> out = recognize_strokes(four_sides(5.0));
  for (const GroupedShape& g : out) EXPECT_LT(g.strokes.size(), 4u);
}

TEST(GroupRecognize, GroupingOffRecognizesEachStrokeAlone) {
  GroupingConfig config;
  config.enabled = false;
  const std::vector<GroupedShape> out = recognize_strokes(four_sides(), config);
  ASSERT_EQ(out.size(), 4u);
  for (const GroupedShape& g : out) EXPECT_EQ(g.recognition.shape, ShapeClass::kSegment);
}

TEST(GroupRecognize, TwoSeparateTrianglesStayTwo) {
  std::vector<StrokeInput> s;
  s.push_back(input(polyline({{0, 0}, {100, 0}, {50, 80}, {0, 0}}, 0)));
  s.push_back(input(polyline({{104, 0}, {204, 0}, {154, 80}, {104, 0}}, 2.0)));
  const std::vector<GroupedShape> out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 2u);
  for (const GroupedShape& g : out) {
    EXPECT_EQ(g.strokes.size(), 1u);
    EXPECT_EQ(g.recognition.shape, ShapeClass::kTriangle);
    expect_independently_certified(g, s);
  }
}

// The width of a polygon from its vertices: the least over the sides of the farthest vertex
// from the side's line.
double polygon_width(const std::vector<PointD>& v) {
  double width = INFINITY;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const PointD a = v[i], b = v[(i + 1) % v.size()];
    const double side = std::hypot(b.x - a.x, b.y - a.y);
    double far = 0.0;
    for (const PointD& p : v) {
      far = std::max(far, std::abs((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / side);
    }
    width = std::min(width, far);
  }
  return width;
}

// Two open halves of a 200 x h rectangle ("[" then "]"): wide, one rectangle of two strokes;
// narrower than 2 epsilon the whole inside lies within epsilon of the outline (any two strokes
// side by side would pass), so two strokes never make such a closed polygon. (Without the rule,
// h = 22..40 came out as two-stroke triangles and rectangles about 1 epsilon wide.)
TEST(GroupRecognize, SeveralStrokesCloseAPolygonOnlyWhenWiderThanTwoEpsilon) {
  int narrow_checked = 0;
  for (const double h : {22.0, 30.0, 40.0, 60.0}) {
    std::vector<StrokeInput> s;
    s.push_back(input(polyline({{100, 0}, {0, 0}, {0, h}, {100, h}}, 0)));
    s.push_back(input(polyline({{100, 0}, {200, 0}, {200, h}, {100, h}}, 1.0)));
    const std::vector<GroupedShape> out = recognize_strokes(s);
    for (const GroupedShape& g : out) {
      const Recognition& r = g.recognition;
      const bool polygon = r.shape == ShapeClass::kRectangle ||
                           r.shape == ShapeClass::kQuadrilateral ||
                           r.shape == ShapeClass::kSquare || r.shape == ShapeClass::kDiamond ||
                           r.shape == ShapeClass::kTriangle;
      if (h == 60.0) {
        ASSERT_EQ(out.size(), 1u);
        EXPECT_EQ(r.shape, ShapeClass::kRectangle) << to_string(r.shape);
        EXPECT_EQ(g.strokes.size(), 2u);
        expect_independently_certified(g, s);
      } else if (g.strokes.size() > 1 && polygon) {
        ASSERT_GE(r.params.vertices.size(), 3u);
        EXPECT_GE(polygon_width(r.params.vertices), 2.0 * r.epsilon)
            << "h = " << h << ": " << to_string(r.shape);
      }
      if (h < 60.0 && 2.0 * r.epsilon > h) ++narrow_checked;
    }
  }
  EXPECT_GT(narrow_checked, 0); // some drawings are narrower than 2 epsilon
}

void expect_arrow(const GroupedShape& g, const std::vector<StrokeInput>& s, PointD tail, PointD tip,
                  std::size_t strokes) {
  const Recognition& r = g.recognition;
  ASSERT_EQ(r.shape, ShapeClass::kArrow) << to_string(r.shape);
  EXPECT_EQ(g.strokes.size(), strokes);
  ASSERT_EQ(r.params.vertices.size(), 4u);
  EXPECT_LT(std::hypot(r.params.vertices[0].x - tail.x, r.params.vertices[0].y - tail.y), 6.0);
  EXPECT_LT(std::hypot(r.params.vertices[1].x - tip.x, r.params.vertices[1].y - tip.y), 6.0);
  // Barbs 50 long at atan(30 / 40) from the shaft.
  EXPECT_NEAR(r.params.head_angle, std::atan2(30.0, 40.0), 0.12);
  EXPECT_TRUE(r.params.shaft_bends.empty()) << "a straight shaft certifies: no bends";
  expect_independently_certified(g, s);
}

TEST(GroupRecognize, ArrowInOneStroke) {
  const std::vector<StrokeInput> s{
      input(polyline({{0, 0}, {200, 0}, {160, 30}, {200, 0}, {160, -30}}, 0))};
  const std::vector<GroupedShape> out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  expect_arrow(out[0], s, {0, 0}, {200, 0}, 1);
}

TEST(GroupRecognize, ArrowAsShaftThenV) {
  std::vector<StrokeInput> s{input(line({0, 0}, {200, 0}, 0))};
  s.push_back(input(polyline({{160, 30}, {200, 0}, {160, -30}}, end_time(s) + 0.3)));
  const std::vector<GroupedShape> out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  expect_arrow(out[0], s, {0, 0}, {200, 0}, 2);
}

// The grouper keeps each pair of strokes' gap across add() calls: each gap must be the pair's own.
// A far stroke is drawn first, so that the head's gap to it is measured before its gap to the
// shaft (the union with the most strokes is tried first); the head still joins the shaft only.
TEST(GroupRecognize, ArrowAfterAFarStrokeGroupsTheShaftAndItsHead) {
  std::vector<StrokeInput> s{input(line({0, 300}, {120, 300}, 0))};
  s.push_back(input(line({0, 0}, {200, 0}, end_time(s) + 0.3)));
  s.push_back(input(polyline({{160, 30}, {200, 0}, {160, -30}}, end_time(s) + 0.3)));
  StrokeGrouper g;
  for (const StrokeInput& in : s) (void)g.add(in);
  const std::vector<GroupedShape> out = g.shapes();
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].strokes, (std::vector<std::size_t>{0}));
  expect_arrow(out[1], s, {0, 0}, {200, 0}, 2);
  EXPECT_EQ(out[1].strokes, (std::vector<std::size_t>{1, 2}));
}

TEST(GroupRecognize, ArrowAsShaftThenTwoBarbs) {
  std::vector<StrokeInput> s{input(line({0, 0}, {200, 0}, 0))};
  s.push_back(input(line({200, 0}, {160, 30}, end_time(s) + 0.3)));
  s.push_back(input(line({160, -30}, {201, 1}, end_time(s) + 0.3)));
  const std::vector<GroupedShape> out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  expect_arrow(out[0], s, {0, 0}, {200, 0}, 3);
}

// A wide head whose long barb ends farther from the tail than the tip does: the two farthest
// points of the drawing are the tail and that barb's end, and the tip must still be found.
TEST(GroupRecognize, ArrowWhoseBarbReachesFartherThanTheTip) {
  const double a1 = 75.0 * std::numbers::pi / 180.0, a2 = 40.0 * std::numbers::pi / 180.0;
  const PointD barb1{200 - 120 * std::cos(a1), 120 * std::sin(a1)};
  const PointD barb2{200 - 60 * std::cos(a2), -60 * std::sin(a2)};
  ASSERT_GT(std::hypot(barb1.x, barb1.y), 200.0); // farther from the tail than the tip
  const std::vector<StrokeInput> s{input(polyline({{0, 0}, {200, 0}, barb1, {200, 0}, barb2}, 0))};
  const std::vector<GroupedShape> out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  const Recognition& r = out[0].recognition;
  ASSERT_EQ(r.shape, ShapeClass::kArrow) << to_string(r.shape);
  ASSERT_EQ(r.params.vertices.size(), 4u);
  EXPECT_LT(std::hypot(r.params.vertices[0].x, r.params.vertices[0].y), 6.0);
  EXPECT_LT(std::hypot(r.params.vertices[1].x - 200, r.params.vertices[1].y), 6.0);
  EXPECT_NEAR(r.params.head_angle, (a1 + a2) / 2, 0.12);
  expect_independently_certified(out[0], s);
}

TEST(GroupRecognize, DoubleArrow) {
  const std::vector<StrokeInput> s{input(polyline(
      {{40, 30}, {0, 0}, {40, -30}, {0, 0}, {200, 0}, {160, 30}, {200, 0}, {160, -30}}, 0))};
  const std::vector<GroupedShape> out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kDoubleArrow);
  EXPECT_EQ(out[0].recognition.params.vertices.size(), 6u);
  expect_independently_certified(out[0], s);
}

// A "hockey stick" arrow: the shaft runs 90 along the x axis, bends by atan(60 / 110) (about
// 29 degrees) and runs on to the tip; the barbs are 45 long at 30 degrees on either side of the
// last piece. Drawn with a known pen (radius 2, so epsilon = 5 radii = 10).
struct HockeyStick {
  PointD tail{0, 0}, bend{90, 0}, tip{200, -60};
  PointD barb(double side) const {
    const double back = std::atan2(bend.y - tip.y, bend.x - tip.x);
    const double a = back + side * std::numbers::pi / 6;
    return {tip.x + 45 * std::cos(a), tip.y + 45 * std::sin(a)};
  }
};

RecognizerConfig known_pen() {
  RecognizerConfig c;
  c.pen_radius = 2.0;
  c.tolerance = 10.0; // what these shapes are drawn against (5 radii; the default follows size)
  return c;
}

void expect_hockey_stick(const GroupedShape& g, const std::vector<StrokeInput>& s,
                         std::size_t strokes) {
  const HockeyStick h;
  const Recognition& r = g.recognition;
  ASSERT_EQ(r.shape, ShapeClass::kArrow) << to_string(r.shape);
  EXPECT_EQ(g.strokes.size(), strokes);
  EXPECT_DOUBLE_EQ(r.epsilon, 10.0);
  ASSERT_EQ(r.params.vertices.size(), 4u);
  EXPECT_EQ(r.params.shaft_bulge, 0.0);
  // Neither a straight nor an arc shaft is within 0.6 epsilon of this ink: one bend, near the
  // drawn one (within 0.6 epsilon, the fit's own slack); tail and tip as well.
  ASSERT_EQ(r.params.shaft_bends.size(), 1u);
  const auto near = [](PointD a, PointD b) { return std::hypot(a.x - b.x, a.y - b.y); };
  EXPECT_LT(near(r.params.shaft_bends[0], h.bend), 6.0);
  EXPECT_LT(near(r.params.vertices[0], h.tail), 6.0);
  EXPECT_LT(near(r.params.vertices[1], h.tip), 6.0);
  // The barbs: each within 6 of a drawn one (either order), head angle 30 degrees.
  for (const PointD b : {r.params.vertices[2], r.params.vertices[3]}) {
    EXPECT_LT(std::min(near(b, h.barb(1)), near(b, h.barb(-1))), 6.0);
  }
  EXPECT_NEAR(r.params.head_angle, std::numbers::pi / 6, 0.12);
  expect_independently_certified(g, s);
}

TEST(GroupRecognize, HockeyStickArrowInOneStrokeHasABentShaft) {
  const HockeyStick h;
  const std::vector<StrokeInput> s{
      input(polyline({h.tail, h.bend, h.tip, h.barb(1), h.tip, h.barb(-1)}, 0))};
  const std::vector<GroupedShape> out = recognize_strokes(s, {}, known_pen());
  ASSERT_EQ(out.size(), 1u);
  expect_hockey_stick(out[0], s, 1);
  // The independent verifier (penshape verify) accepts the answer, and refutes it with the bend
  // moved 2 epsilon away from the corner (along the outer bisector of the drawn shaft).
  const Recognition& r = out[0].recognition;
  ASSERT_EQ(r.params.shaft_bends.size(), 1u);
  const std::vector<std::vector<PointD>> paths = test::paths_of(s, {0});
  RecognitionClaim claim{r.shape, r.params, r.epsilon, r.pen_radius};
  EXPECT_EQ(verify_recognition(paths, claim).status, VerifyStatus::kVerified);
  const double in = std::hypot(h.tail.x - h.bend.x, h.tail.y - h.bend.y);
  const double on = std::hypot(h.tip.x - h.bend.x, h.tip.y - h.bend.y);
  const PointD sum{(h.tail.x - h.bend.x) / in + (h.tip.x - h.bend.x) / on,
                   (h.tail.y - h.bend.y) / in + (h.tip.y - h.bend.y) / on};
  const double away = -2.0 * r.epsilon / std::hypot(sum.x, sum.y);
  claim.params.shaft_bends[0].x += away * sum.x;
  claim.params.shaft_bends[0].y += away * sum.y;
  EXPECT_EQ(verify_recognition(paths, claim).status, VerifyStatus::kRefuted);
}

TEST(GroupRecognize, HockeyStickShaftThenVHasABentShaft) {
  const HockeyStick h;
  std::vector<StrokeInput> s{input(polyline({h.tail, h.bend, h.tip}, 0))};
  s.push_back(input(polyline({h.barb(1), h.tip, h.barb(-1)}, end_time(s) + 0.3)));
  const std::vector<GroupedShape> out = recognize_strokes(s, {}, known_pen());
  ASSERT_EQ(out.size(), 1u);
  expect_hockey_stick(out[0], s, 2);
}

// A shaft that doubles back (turns by 150 degrees: a hook, not a shaft leading to its tip) is
// not a bent arrow, even with a head drawn at its end.
TEST(GroupRecognize, ShaftThatDoublesBackIsNoArrow) {
  const PointD tail{0, 0}, bend{150, 0}, tip{20, 75}; // turn: 180 - atan(75 / 130) = 150 deg
  const double back = std::atan2(bend.y - tip.y, bend.x - tip.x);
  auto barb = [&](double side) {
    const double a = back + side * std::numbers::pi / 6;
    return PointD{tip.x + 40 * std::cos(a), tip.y + 40 * std::sin(a)};
  };
  const std::vector<StrokeInput> s{input(polyline({tail, bend, tip, barb(1), tip, barb(-1)}, 0))};
  const std::vector<GroupedShape> out = recognize_strokes(s, {}, known_pen());
  for (const GroupedShape& g : out) {
    EXPECT_NE(g.recognition.shape, ShapeClass::kArrow);
    EXPECT_NE(g.recognition.shape, ShapeClass::kDoubleArrow);
  }
}

TEST(GroupRecognize, TidyTurnsANearlyAxisParallelRectangleOntoTheAxes) {
  const double a = 3.0 * std::numbers::pi / 180;
  std::vector<PointD> c;
  for (const PointD p : {PointD{0, 0}, PointD{200, 0}, PointD{200, 120}, PointD{0, 120}}) {
    c.push_back({std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y});
  }
  c.push_back(c.front());
  const std::vector<StrokeInput> s{input(polyline(c, 0))};
  const std::vector<GroupedShape> out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  const Recognition& r = out[0].recognition;
  ASSERT_EQ(r.shape, ShapeClass::kRectangle);
  EXPECT_NE(std::find(out[0].tidy.begin(), out[0].tidy.end(), "axis"), out[0].tidy.end());
  const std::vector<PointD>& v = r.params.vertices;
  for (std::size_t i = 0; i < 4; ++i) { // every side horizontal or vertical
    const PointD d{v[(i + 1) % 4].x - v[i].x, v[(i + 1) % 4].y - v[i].y};
    EXPECT_LT(std::min(std::abs(d.x), std::abs(d.y)), 1e-6 * std::hypot(d.x, d.y));
  }
  expect_independently_certified(out[0], s);
}

TEST(GroupRecognize, TidyIsSkippedWhenItWouldNotCertify) {
  // 9 degrees off the axis with a tight tolerance: turning it would leave the ink.
  const double a = 9.0 * std::numbers::pi / 180;
  std::vector<PointD> c;
  for (const PointD p : {PointD{0, 0}, PointD{200, 0}, PointD{200, 120}, PointD{0, 120}}) {
    c.push_back({std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y});
  }
  c.push_back(c.front());
  RecognizerConfig rc;
  rc.tolerance = 6.0;
  const std::vector<StrokeInput> s{input(polyline(c, 0))};
  const std::vector<GroupedShape> out = recognize_strokes(s, {}, rc);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(std::find(out[0].tidy.begin(), out[0].tidy.end(), "axis"), out[0].tidy.end());
  expect_independently_certified(out[0], s);
}

TEST(GroupRecognize, TidyPrefersACircleToANearCircularEllipse) {
  std::vector<StrokePoint> e;
  for (int k = 0; k <= 200; ++k) {
    const double t = 2 * std::numbers::pi * k / 200.0;
    e.push_back({100 * std::cos(t), 92 * std::sin(t), 0.01 * k});
  }
  RecognizerConfig rc;
  rc.tolerance = 8.0; // the ellipse fits far better, the circle still certifies
  const std::vector<StrokeInput> s{input(e)};
  const std::vector<GroupedShape> out = recognize_strokes(s, {}, rc);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kCircle);
  EXPECT_NE(std::find(out[0].tidy.begin(), out[0].tidy.end(), "circle"), out[0].tidy.end());
  expect_independently_certified(out[0], s);
}

TEST(GroupRecognize, TidyConnectsALineToARecentShapesCorner) {
  std::vector<StrokeInput> s{input(polyline({{0, 0}, {100, 0}, {100, 100}, {0, 100}, {0, 0}}, 0))};
  // A line from 3 px off the square's corner (100, 100) going away from it, 5 s later (its own
  // drawing: grouping cannot merge it, tidy-up may still connect it).
  s.push_back(input(line({103, 102}, {250, 190}, 5.0)));
  const std::vector<GroupedShape> out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 2u);
  const GroupedShape& seg = out[1];
  ASSERT_EQ(seg.recognition.shape, ShapeClass::kSegment);
  EXPECT_NE(std::find(seg.tidy.begin(), seg.tidy.end(), "connection"), seg.tidy.end());
  const PointD end = seg.recognition.params.vertices.front();
  PointD corner = out[0].recognition.params.vertices.at(0);
  for (const PointD& v : out[0].recognition.params.vertices) {
    if (std::hypot(v.x - 100, v.y - 100) < std::hypot(corner.x - 100, corner.y - 100)) corner = v;
  }
  EXPECT_EQ(end.x, corner.x);
  EXPECT_EQ(end.y, corner.y);
  expect_independently_certified(seg, s);
}

TEST(GroupRecognize, BadStrokesAreRefusedAndNotAdded) {
  StrokeGrouper g;
  EXPECT_EQ(g.add(input({{1, 1, 0}})).shape.recognition.shape, ShapeClass::kDot); // issue 23
  EXPECT_THROW(g.add(input({{1, 1, 0}, {NAN, 2, 0.1}})), InvalidInput);
  EXPECT_EQ(g.stroke_count(), 1u);
  EXPECT_THROW(recognize_union({}), InvalidInput);
  GroupingConfig bad;
  bad.max_strokes = 0;
  EXPECT_THROW(StrokeGrouper{bad}, InvalidInput);
}

} // namespace
} // namespace penshape
