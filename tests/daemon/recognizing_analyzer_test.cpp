// The daemon's recognizing analyzer certifies snaps on the ink polygon it reports: a drawn
// circle comes back as a circle whose certificate says "ink-hausdorff-sampling", with the bound
// within the tolerance and the ink polygon present; a scribble stays freeform.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <thread>
#include <vector>

#include "penshape/daemon/recognizing_analyzer.hpp"

namespace penshape::daemon {
namespace {

Stroke stroke_from(const std::vector<PointD>& mm) {
  Stroke s;
  s.id = 7;
  s.tablet.x_max = 40000;
  s.tablet.y_max = 30000;
  s.tablet.x_resolution = 100; // units per mm
  s.tablet.y_resolution = 100;
  s.tablet.pressure_max = 1023;
  std::int64_t t = 0;
  for (const PointD& p : mm) {
    PenSample ps;
    ps.time_us = t += 5000;
    ps.x = static_cast<std::int32_t>(std::lround(p.x * 100));
    ps.y = static_cast<std::int32_t>(std::lround(p.y * 100));
    ps.pressure = 600;
    ps.in_range = ps.tip = true;
    s.samples.push_back(ps);
  }
  s.samples.back().tip = false;
  return s;
}

TEST(RecognizingAnalyzer, CircleIsCertifiedOnTheInk) {
  std::vector<PointD> mm;
  for (int k = 0; k <= 200; ++k) {
    const double t = 2 * std::numbers::pi * k / 200.0;
    mm.push_back({100 + 30 * std::cos(t) + 0.2 * std::sin(7 * t), 80 + 30 * std::sin(t)});
  }
  mm.push_back(mm[1]); // the overlap a closing hand draws, then tip up
  const auto analyzer = make_recognizing_analyzer();
  PenSettings settings;
  settings.pen_radius_mm = 0.8;
  const StrokeAnalysis a = analyzer->analyze(stroke_from(mm), settings, {});
  EXPECT_GT(a.ink_polygon.polygons_size(), 0);
  ASSERT_EQ(a.shape.kind(), v1::SHAPE_KIND_CIRCLE);
  EXPECT_EQ(a.shape.certificate().method(), "ink-hausdorff-sampling");
  EXPECT_LE(a.shape.certificate().hausdorff_bound().approx(),
            a.shape.certificate().tolerance().approx());
  EXPECT_NEAR(a.shape.circle().radius(), 30, 1.0);
  EXPECT_DOUBLE_EQ(a.shape.certificate().pen_radius().approx(), 0.8);
}

// Points along the polyline through `corners`, 40 per side.
std::vector<PointD> along(const std::vector<PointD>& corners) {
  std::vector<PointD> mm;
  for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
    for (int k = 0; k < 40; ++k) {
      const double f = k / 40.0;
      mm.push_back({corners[i].x + f * (corners[i + 1].x - corners[i].x),
                    corners[i].y + f * (corners[i + 1].y - corners[i].y)});
    }
  }
  mm.push_back(corners.back());
  return mm;
}

TEST(RecognizingAnalyzer, AnLShapedHexagonIsAPolygon) {
  const std::vector<PointD> mm =
      along({{20, 20}, {80, 20}, {80, 44}, {44, 44}, {44, 80}, {20, 80}, {20, 20}});
  const auto analyzer = make_recognizing_analyzer();
  PenSettings settings;
  settings.pen_radius_mm = 0.5;
  const StrokeAnalysis a = analyzer->analyze(stroke_from(mm), settings, {});
  ASSERT_EQ(a.shape.kind(), v1::SHAPE_KIND_POLYGON);
  EXPECT_EQ(a.shape.vertices().vertices_size(), 6);
  EXPECT_LE(a.shape.certificate().hausdorff_bound().approx(),
            a.shape.certificate().tolerance().approx());
}

TEST(RecognizingAnalyzer, ARhombusOfSixtyDegreesIsADiamond) {
  // Half-diagonals 30 and 30 tan 30 degrees, the long one turned 20 degrees, centre (50, 50).
  const double t = 20 * std::numbers::pi / 180, a = 30, b = 30 * std::tan(std::numbers::pi / 6);
  const PointD u{std::cos(t), std::sin(t)}, v{-u.y, u.x}, c{50, 50};
  const PointD p0{c.x + a * u.x, c.y + a * u.y}, p1{c.x + b * v.x, c.y + b * v.y};
  const PointD p2{c.x - a * u.x, c.y - a * u.y}, p3{c.x - b * v.x, c.y - b * v.y};
  const auto analyzer = make_recognizing_analyzer();
  PenSettings settings;
  settings.pen_radius_mm = 0.5;
  const StrokeAnalysis r =
      analyzer->analyze(stroke_from(along({p0, p1, p2, p3, p0})), settings, {});
  ASSERT_EQ(r.shape.kind(), v1::SHAPE_KIND_DIAMOND);
  EXPECT_EQ(r.shape.vertices().vertices_size(), 4);
  EXPECT_LE(r.shape.certificate().hausdorff_bound().approx(),
            r.shape.certificate().tolerance().approx());
}

TEST(RecognizingAnalyzer, ScribbleStaysInk) {
  std::vector<PointD> mm;
  for (int k = 0; k <= 400; ++k) {
    const double t = k / 400.0;
    mm.push_back({100 + 60 * t + 4 * std::sin(40 * t), 80 + 6 * std::cos(33 * t)});
  }
  const auto analyzer = make_recognizing_analyzer();
  const StrokeAnalysis a = analyzer->analyze(stroke_from(mm), PenSettings{}, {});
  EXPECT_GT(a.ink_polygon.polygons_size(), 0);
  EXPECT_EQ(a.shape.kind(), v1::SHAPE_KIND_NONE);
}

// Previews while the pen moves: the analyzer is handed the stroke so far, again and again (the
// pipeline's preview lane); a circle is previewed as one before pen-up, and a cancelled preview
// (the stroke ended) throws Cancelled.
TEST(RecognizingAnalyzer, PreviewsAGrowingCircleAndStopsWhenCancelled) {
  std::vector<PointD> mm;
  for (int k = 0; k <= 200; ++k) {
    const double t = 2 * std::numbers::pi * k / 200.0;
    mm.push_back({100 + 30 * std::cos(t), 80 + 30 * std::sin(t)});
  }
  const Stroke whole = stroke_from(mm);
  const auto analyzer = make_recognizing_analyzer();
  PenSettings settings;
  settings.pen_radius_mm = 0.8;
  v1::ShapeKind last = v1::SHAPE_KIND_UNSPECIFIED;
  for (std::size_t n = 20; n <= 190; n += 10) {
    Stroke partial = whole;
    partial.samples.resize(n);
    const auto shapes = analyzer->preview(partial, settings, {});
    const auto again = analyzer->preview(partial, settings, {}); // nothing new: same answer
    ASSERT_EQ(shapes.size(), again.size());
    if (!shapes.empty()) {
      EXPECT_EQ(shapes[0].kind(), again[0].kind());
      EXPECT_FALSE(shapes[0].has_certificate()); // a preview is not certified
      last = shapes[0].kind();
    }
  }
  EXPECT_EQ(last, v1::SHAPE_KIND_CIRCLE) << "at 95% of a circle the preview is a circle";

  Stroke next = whole;
  next.id = 8;
  EXPECT_THROW((void)analyzer->preview(next, settings, [] { return true; }), Cancelled);
}

// Several strokes at once (Geometry.Recognize with `strokes`): a shaft and a "V" head are one
// arrow covering both strokes; a far-away segment stays its own group.
TEST(RecognizingAnalyzer, GroupsAShaftAndItsHeadIntoOneArrow) {
  auto line = [](PointD a, PointD b) {
    std::vector<PointD> out;
    for (int k = 0; k <= 40; ++k)
      out.push_back({a.x + (b.x - a.x) * k / 40.0, a.y + (b.y - a.y) * k / 40.0});
    return out;
  };
  std::vector<PointD> head = line({76, 86}, {90, 80});
  const std::vector<PointD> second = line({90, 80}, {76, 74});
  head.insert(head.end(), second.begin() + 1, second.end());
  std::vector<Stroke> strokes{stroke_from(line({20, 80}, {90, 80})), stroke_from(head),
                              stroke_from(line({20, 150}, {90, 150}))};
  for (std::size_t i = 0; i < strokes.size(); ++i) { // drawn one after the other
    for (PenSample& s : strokes[i].samples) s.time_us += static_cast<std::int64_t>(i) * 1'000'000;
  }
  const auto analyzer = make_recognizing_analyzer();
  PenSettings settings;
  settings.pen_radius_mm = 0.5;
  settings.snap_writing = true; // grouping and dots alone (a dot is writing: intent_e2e_test)
  const std::vector<v1::RecognizedGroup> groups =
      analyzer->recognize_group(strokes, settings, GroupingConfig{});
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].shape().kind(), v1::SHAPE_KIND_ARROW);
  ASSERT_EQ(groups[0].strokes_size(), 2);
  EXPECT_EQ(groups[0].strokes(0), 0u);
  EXPECT_EQ(groups[0].strokes(1), 1u);
  EXPECT_NEAR(groups[0].shape().arrow().tip().x(), 90, 1.0);
  EXPECT_NEAR(groups[0].shape().arrow().tail().x(), 20, 1.0);
  EXPECT_EQ(groups[0].shape().arrow().barbs_size(), 2);
  EXPECT_LE(groups[0].shape().certificate().hausdorff_bound().approx(),
            groups[0].shape().certificate().tolerance().approx());
  ASSERT_EQ(groups[1].strokes_size(), 1);
  EXPECT_EQ(groups[1].shape().kind(), v1::SHAPE_KIND_SEGMENT);
  // A dot is a stroke (issue 23), in the group call and alone.
  const auto dots = analyzer->recognize_group({stroke_from({{1, 1}, {1, 1}})}, settings, {});
  ASSERT_EQ(dots.size(), 1u);
  EXPECT_EQ(dots[0].shape().kind(), v1::SHAPE_KIND_DOT);
  const StrokeAnalysis dot = analyzer->analyze(stroke_from({{5, 5}, {5, 5}, {5, 5}}), settings, {});
  EXPECT_EQ(dot.shape.kind(), v1::SHAPE_KIND_DOT);
  ASSERT_EQ(dot.shape.vertices().vertices_size(), 1);
  EXPECT_NEAR(dot.shape.vertices().vertices(0).x(), 5, 1e-9);
}

// A circle of radius 30 mm around (100, 80), closed with the overlap a hand draws.
std::vector<PointD> closed_circle() {
  std::vector<PointD> circle;
  for (int k = 0; k <= 200; ++k) {
    const double t = 2 * std::numbers::pi * k / 200.0;
    circle.push_back({100 + 30 * std::cos(t), 80 + 30 * std::sin(t)});
  }
  circle.push_back(circle[1]);
  return circle;
}

// The daemon's strand builds a stroke's ink polygon Q on a helper worker and hands the shape out
// before Q when it did not read Q (InkOffload::shape_first): the answers and the ink are those of
// a session that builds everything on one thread, with a helper started at once or not at all.
TEST(RecognizingAnalyzer, GroupSessionAnswersTheSameWithTheInkBuiltElsewhere) {
  std::vector<Stroke> strokes{stroke_from(closed_circle()),
                              stroke_from(along({{20, 20}, {90, 20}})),
                              stroke_from(along({{90, 20}, {90, 60}, {20, 60}, {20, 20}}))};
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    strokes[i].id = 10 + i;
    for (PenSample& s : strokes[i].samples) s.time_us += static_cast<std::int64_t>(i) * 1'000'000;
  }
  const auto analyzer = make_recognizing_analyzer();
  PenSettings settings;
  settings.pen_radius_mm = 0.8;
  settings.snap_writing = true;
  std::vector<std::function<void()>> not_started; // a helper that starts only after add()
  InkOffload late;
  late.run_elsewhere = [&not_started](std::function<void()> job) {
    not_started.push_back(std::move(job));
    return true;
  };
  late.shape_first = true;
  std::vector<std::thread> threads; // a helper that starts at once
  InkOffload eager;
  eager.run_elsewhere = [&threads](std::function<void()> job) {
    threads.emplace_back(std::move(job));
    return true;
  };
  eager.shape_first = true;
  auto serial = analyzer->group_session(settings, GroupingConfig{});
  auto later = analyzer->group_session(settings, GroupingConfig{});
  auto helped = analyzer->group_session(settings, GroupingConfig{});
  bool certified_on_ink = false;
  for (const Stroke& stroke : strokes) {
    const GroupedStrokeAnalysis a = serial->add(stroke, true, {});
    GroupedStrokeAnalysis b = later->add(stroke, true, {}, late);
    GroupedStrokeAnalysis c = helped->add(stroke, true, {}, eager);
    // Q is handed over later exactly when the answer did not read it (StrokeFinished then
    // follows the shape); a shape certified on Q carries Q.
    const bool read_q = a.analysis.shape.certificate().method() == "ink-hausdorff-sampling";
    EXPECT_EQ(static_cast<bool>(b.ink_later), !read_q);
    b.wait_ink();
    c.wait_ink();
    for (auto& job : not_started) job(); // finds Q and its proto form built: does nothing
    not_started.clear();
    EXPECT_EQ(a.analysis.shape.SerializeAsString(), b.analysis.shape.SerializeAsString());
    EXPECT_EQ(a.analysis.shape.SerializeAsString(), c.analysis.shape.SerializeAsString());
    EXPECT_EQ(a.analysis.ink_polygon.SerializeAsString(),
              b.analysis.ink_polygon.SerializeAsString());
    EXPECT_EQ(a.analysis.ink_polygon.SerializeAsString(),
              c.analysis.ink_polygon.SerializeAsString());
    EXPECT_GT(a.analysis.ink_polygon.polygons_size(), 0);
    EXPECT_EQ(a.strokes, b.strokes);
    EXPECT_EQ(a.strokes, c.strokes);
    certified_on_ink |= a.analysis.shape.certificate().method() == "ink-hausdorff-sampling";
  }
  for (std::thread& t : threads) t.join();
  EXPECT_TRUE(certified_on_ink); // the strand read Q for at least one answer
}

// A hold's work ahead (on a copy of the session, as try_hold does) is cancelled when a pen-up
// overtakes it: a call whose cancel hook turns true while the stroke is fitted stops when it
// would wait for Q (Cancelled); the session then answers the pen-up as a fresh one.
TEST(RecognizingAnalyzer, AHeldStrokeCancelledDuringItsFitsStopsBeforeTheInk) {
  const Stroke stroke = stroke_from(closed_circle());
  const auto analyzer = make_recognizing_analyzer();
  PenSettings settings;
  settings.pen_radius_mm = 0.8;
  auto session = analyzer->group_session(settings, GroupingConfig{});
  int asked = 0;
  const CancelHook after_the_start = [&asked] { return ++asked > 1; }; // false at the start only
  EXPECT_THROW((void)session->clone()->add_held(stroke, after_the_start, {}), Cancelled);
  EXPECT_GT(asked, 1);
  const GroupedStrokeAnalysis again = session->add(stroke, true, {});
  const GroupedStrokeAnalysis fresh =
      analyzer->group_session(settings, GroupingConfig{})->add(stroke, true, {});
  EXPECT_EQ(again.analysis.shape.certificate().method(), "ink-hausdorff-sampling");
  EXPECT_EQ(again.analysis.shape.SerializeAsString(), fresh.analysis.shape.SerializeAsString());
}

// A live grouping session keeps only the strokes its window can reach: through 200 short strokes
// apart from each other, 0.1 s apart (all within the 2 s pause window), the strokes it keeps never
// exceed the groups a stroke may join (6) times (max_strokes - 1), the oldest kept is recent, and
// the session still counts every stroke.
TEST(RecognizingAnalyzer, GroupSessionMemoryFollowsTheWindow) {
  const auto analyzer = make_recognizing_analyzer();
  PenSettings settings;
  settings.pen_radius_mm = 0.5;
  settings.snap_writing = true; // 200 small strokes in rows: writing, never grouped, else
  GroupingConfig grouping;
  grouping.max_strokes = 4;
  const auto session = analyzer->group_session(settings, grouping);
  ASSERT_NE(session, nullptr);
  for (int i = 0; i < 200; ++i) {
    const int row = i / 20;
    const PointD o{20.0 * (i % 20), 20.0 * row}; // 14 mm gaps: beyond any group's epsilon
    std::vector<PointD> mm;
    for (int k = 0; k <= 12; ++k) mm.push_back({o.x + 0.5 * k, o.y + 0.1 * std::sin(k)});
    Stroke s = stroke_from(mm);
    s.id = static_cast<std::uint64_t>(i);
    for (PenSample& p : s.samples) p.time_us += static_cast<std::int64_t>(i) * 100'000;
    const GroupedStrokeAnalysis r = session->add(s, false, {});
    ASSERT_TRUE(r.grouped);
    EXPECT_EQ(r.strokes, std::vector<std::size_t>{static_cast<std::size_t>(i)}) << "stroke " << i;
    EXPECT_LE(session->retained_stroke_count(), 6U * 3U) << "stroke " << i;
    EXPECT_GE(session->oldest_retained_stroke() + std::size_t{6} * 4U, static_cast<std::size_t>(i));
  }
  EXPECT_EQ(session->stroke_count(), 200U);
}

// An arrow with a bent shaft through the proto and back: to_proto_shape, serialized and parsed
// again, keeps the bends in order (tail to tip) beside the other arrow fields.
TEST(RecognizingAnalyzer, BentShaftArrowRoundTripsThroughTheProto) {
  ShapeParams p;
  p.vertices = {{0, 0}, {100, -30}, {90, -16}, {84, -24}, {8, 6}, {8, -6}};
  p.shaft_bends = {{40, 2}, {60, 0}};
  p.head_angle = 0.5;
  const v1::Shape shape =
      to_proto_shape(ShapeClass::kDoubleArrow, p, {{0, 0}, {100, -30}}, Certificate{}, 0.9);
  std::string bytes;
  ASSERT_TRUE(shape.SerializeToString(&bytes));
  v1::Shape back;
  ASSERT_TRUE(back.ParseFromString(bytes));
  ASSERT_TRUE(back.has_arrow());
  EXPECT_EQ(back.kind(), v1::SHAPE_KIND_DOUBLE_ARROW);
  const v1::ArrowParams& a = back.arrow();
  ASSERT_EQ(a.shaft_bends_size(), 2);
  EXPECT_EQ(a.shaft_bends(0).x(), 40);
  EXPECT_EQ(a.shaft_bends(0).y(), 2);
  EXPECT_EQ(a.shaft_bends(1).x(), 60);
  EXPECT_EQ(a.shaft_bends(1).y(), 0);
  EXPECT_EQ(a.shaft_bulge(), 0);
  EXPECT_EQ(a.tip().x(), 100);
  EXPECT_EQ(a.tail_barbs_size(), 2);
  EXPECT_EQ(a.barbs(1).x(), 84);
  EXPECT_EQ(a.head_angle_rad(), 0.5);
  // A straight shaft has none.
  p.shaft_bends.clear();
  EXPECT_EQ(to_proto_shape(ShapeClass::kDoubleArrow, p, {}, Certificate{}, 0.9)
                .arrow()
                .shaft_bends_size(),
            0);
}

// A "hockey stick" arrow drawn in one stroke (shaft 35 mm along x, then bent by about 29 degrees
// to the tip; barbs 12 mm at 30 degrees to the last piece) comes back from the daemon with its
// bend, near the drawn one, and certified.
TEST(RecognizingAnalyzer, HockeyStickArrowKeepsItsBend) {
  const PointD tail{20, 100}, bend{65, 100}, tip{120, 70};
  const double back = std::atan2(bend.y - tip.y, bend.x - tip.x);
  auto barb = [&](double side) {
    const double a = back + side * std::numbers::pi / 6;
    return PointD{tip.x + 25 * std::cos(a), tip.y + 25 * std::sin(a)}; // well above epsilon
  };
  std::vector<PointD> mm;
  const std::vector<PointD> corners{tail, bend, tip, barb(1), tip, barb(-1)};
  for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
    for (int k = i == 0 ? 0 : 1; k <= 40; ++k) {
      const double f = k / 40.0;
      mm.push_back({corners[i].x + f * (corners[i + 1].x - corners[i].x),
                    corners[i].y + f * (corners[i + 1].y - corners[i].y)});
    }
  }
  const auto analyzer = make_recognizing_analyzer();
  PenSettings settings;
  settings.pen_radius_mm = 0.5;
  const std::vector<v1::RecognizedGroup> groups =
      analyzer->recognize_group({stroke_from(mm)}, settings, GroupingConfig{});
  ASSERT_EQ(groups.size(), 1u);
  ASSERT_EQ(groups[0].shape().kind(), v1::SHAPE_KIND_ARROW);
  const v1::ArrowParams& a = groups[0].shape().arrow();
  ASSERT_EQ(a.shaft_bends_size(), 1);
  // Within 0.6 epsilon of the drawn bend (epsilon follows the size: recognize.hpp).
  EXPECT_LT(std::hypot(a.shaft_bends(0).x() - bend.x, a.shaft_bends(0).y() - bend.y),
            0.6 * groups[0].shape().certificate().tolerance().approx());
  EXPECT_LE(groups[0].shape().certificate().hausdorff_bound().approx(),
            groups[0].shape().certificate().tolerance().approx());
}

} // namespace
} // namespace penshape::daemon
