// Hold to snap, the parts without a daemon: when a hold is satisfied (HoldDetector on sample
// times, at 200 Hz and 1 kHz), what a drag after it is (tremor within hold_radius_mm is not), how
// the held shape follows the pen, and the config keys and Config fields with their checks.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hold_follow.hpp"
#include "hold_state.hpp"
#include "penshape/daemon/config.hpp"
#include "penshape/daemon/proto_convert.hpp"

namespace {

namespace d = penshape::daemon;
namespace v1 = penshape::v1;

penshape::TabletInfo tablet_mm(double units_per_mm) {
  penshape::TabletInfo t;
  t.x_resolution = units_per_mm;
  t.y_resolution = units_per_mm;
  t.x_max = 100000;
  t.y_max = 100000;
  return t;
}

penshape::PenSample at(double x_mm, double y_mm, std::int64_t time_us, double units_per_mm) {
  penshape::PenSample s;
  s.x = static_cast<std::int32_t>(std::lround(x_mm * units_per_mm));
  s.y = static_cast<std::int32_t>(std::lround(y_mm * units_per_mm));
  s.time_us = time_us;
  s.tip = true;
  s.in_range = true;
  return s;
}

// The first sample time (us) at which the detector fires, or -1: the pen moves for 0.3 s, then
// trembles by `tremor_mm` around one point for `still_s`.
std::int64_t hold_time(double rate_hz, double tremor_mm, double still_s) {
  d::PenSettings settings; // hold_ms 500, hold_radius_mm 1
  const double res = 100;
  d::HoldDetector detector(settings, tablet_mm(res));
  const auto period = static_cast<std::int64_t>(1e6 / rate_hz);
  std::int64_t t = 0;
  for (; t < 300000; t += period) {
    if (detector.add(at(10 + 0.1 * static_cast<double>(t) / 1000, 10, t, res))) return t;
  }
  const std::int64_t rest = t;
  for (int i = 0; t < rest + static_cast<std::int64_t>(still_s * 1e6); t += period, ++i) {
    const double wobble = tremor_mm * ((i % 2 == 0) ? 1 : -1);
    if (detector.add(at(40 + wobble, 10 - wobble, t, res))) return t - rest;
  }
  return -1;
}

TEST(HoldDetector, FiresAfterHoldMsOfTremorWithinTheRadiusAt200HzAnd1kHz) {
  for (const double rate : {200.0, 1000.0}) {
    SCOPED_TRACE(rate);
    const std::int64_t after = hold_time(rate, 0.3, 0.8);
    const auto period = static_cast<std::int64_t>(1e6 / rate);
    // The rest may start a sample or two early: the last moving samples are within the radius.
    EXPECT_GE(after, 500000 - 3 * period);
    EXPECT_LE(after, 500000 + 2 * period);
    EXPECT_EQ(hold_time(rate, 0.3, 0.45), -1) << "shorter than hold_ms";
    EXPECT_EQ(hold_time(rate, 0.6, 0.8), -1) << "trembling by 1.2 mm > hold_radius_mm";
  }
}

TEST(HoldDetector, MovingPenNeverHolds) {
  d::PenSettings settings;
  d::HoldDetector detector(settings, tablet_mm(100));
  for (std::int64_t t = 0; t < 5'000'000; t += 5000) {
    // 3 mm/s: slow drawing, still faster than hold_radius_mm per hold_ms.
    ASSERT_FALSE(detector.add(at(3.0 * static_cast<double>(t) / 1e6, 5, t, 100)));
  }
}

TEST(HoldDetector, SettlesOncePerRestAfterAQuarterOfHoldMs) {
  d::PenSettings settings; // hold_ms 500, hold_radius_mm 1
  d::HoldDetector detector(settings, tablet_mm(100));
  std::vector<std::int64_t> settled; // the rest's age (us) at each settled()
  std::int64_t rest = 0;
  std::int64_t t = 0;
  const auto add = [&](double x_mm) {
    EXPECT_FALSE(detector.add(at(x_mm, 10, t, 100)));
    if (detector.settled()) settled.push_back(t - rest);
  };
  for (; t < 200000; t += 1000) add(10 + 0.1 * static_cast<double>(t) / 1000); // moving
  EXPECT_TRUE(settled.empty()) << "a moving pen never settles";
  rest = t;
  for (; t < rest + 300000; t += 1000) add(40); // rests 0.3 s: settles once
  rest = t;
  for (; t < rest + 300000; t += 1000) add(45); // rests again elsewhere: once more
  ASSERT_EQ(settled.size(), 2U);
  EXPECT_EQ(settled[0], 125000);
  EXPECT_EQ(settled[1], 125000);
}

TEST(HoldDrag, TremorIsNotADragLeavingTheRadiusIs) {
  d::HoldState hold;
  hold.point = {40, 10};
  hold.radius_mm = 1.0;
  hold.time_us = 1000;
  penshape::Stroke stroke;
  stroke.tablet = tablet_mm(100);
  stroke.samples.push_back(at(0, 0, 0, 100));
  stroke.samples.push_back(at(40.5, 10.5, 2000, 100)); // within 1 mm
  stroke.samples.push_back(at(39.4, 10.2, 3000, 100));
  d::Drag drag = d::drag_after_hold(stroke, hold);
  EXPECT_FALSE(drag.dragged);
  stroke.samples.push_back(at(45, 10, 4000, 100));   // 5 mm away
  stroke.samples.push_back(at(40.2, 10, 5000, 100)); // back near the hold: still a drag
  drag = d::drag_after_hold(stroke, hold);
  EXPECT_TRUE(drag.dragged);
  EXPECT_NEAR(drag.tip.x, 40.2, 1e-9);
}

v1::Shape vertices(v1::ShapeKind kind, std::initializer_list<std::pair<double, double>> points) {
  v1::Shape s;
  s.set_kind(kind);
  for (const auto& [x, y] : points) {
    v1::Point* p = s.mutable_vertices()->add_vertices();
    p->set_x(x);
    p->set_y(y);
  }
  s.mutable_certificate()->set_method("ink-hausdorff-sampling");
  return s;
}

void expect_point(const v1::Point& p, double x, double y) {
  EXPECT_NEAR(p.x(), x, 1e-9);
  EXPECT_NEAR(p.y(), y, 1e-9);
}

TEST(FollowShape, ASegmentsEndFollowsTheTip) {
  const v1::Shape held = vertices(v1::SHAPE_KIND_SEGMENT, {{0, 0}, {10, 0}});
  const v1::Shape moved = d::follow_shape(held, {10.2, 0.1}, {10.2, 5.1});
  expect_point(moved.vertices().vertices(0), 0, 0);
  expect_point(moved.vertices().vertices(1), 10, 5);
  EXPECT_EQ(moved.certificate().scope(), "drawn_part+user_edit");
  EXPECT_EQ(moved.certificate().method(), "ink-hausdorff-sampling");
}

TEST(FollowShape, ACirclesRadiusFollowsTheTip) {
  v1::Shape held;
  held.set_kind(v1::SHAPE_KIND_CIRCLE);
  held.mutable_circle()->mutable_center()->set_x(5);
  held.mutable_circle()->mutable_center()->set_y(5);
  held.mutable_circle()->set_radius(10);
  v1::Segment* piece = held.mutable_clean_path()->add_pieces()->mutable_segment();
  piece->mutable_start()->set_x(15);
  piece->mutable_start()->set_y(5);
  piece->mutable_end()->set_x(5);
  piece->mutable_end()->set_y(15);
  const v1::Shape moved = d::follow_shape(held, {15, 5}, {5, 23}); // 18 mm from the center
  EXPECT_NEAR(moved.circle().radius(), 18, 1e-9);
  expect_point(moved.circle().center(), 5, 5);
  expect_point(moved.clean_path().pieces(0).segment().start(), 23, 5);
  expect_point(moved.clean_path().pieces(0).segment().end(), 5, 23);
}

TEST(FollowShape, ARectanglesOppositeCornerFollowsTheTipItsDirectionsKept) {
  // A rectangle turned by 90 degrees: sides along y then x.
  const v1::Shape held = vertices(v1::SHAPE_KIND_RECTANGLE, {{0, 0}, {0, 10}, {-20, 10}, {-20, 0}});
  const v1::Shape moved = d::follow_shape(held, {-20, 10}, {-30, 14});
  expect_point(moved.vertices().vertices(0), 0, 0);
  expect_point(moved.vertices().vertices(1), 0, 14);
  expect_point(moved.vertices().vertices(2), -30, 14);
  expect_point(moved.vertices().vertices(3), -30, 0);
}

TEST(FollowShape, APolygonIsScaledAndRotatedAboutItsFirstPoint) {
  const v1::Shape held = vertices(v1::SHAPE_KIND_TRIANGLE, {{1, 1}, {11, 1}, {1, 11}});
  // The hold at the second vertex; the tip at twice the distance, a quarter turn further.
  const v1::Shape moved = d::follow_shape(held, {11, 1}, {1, 21});
  expect_point(moved.vertices().vertices(0), 1, 1);
  expect_point(moved.vertices().vertices(1), 1, 21);
  expect_point(moved.vertices().vertices(2), -19, 1);
}

TEST(HoldConfig, KeysAndDefaults) {
  const d::DaemonConfig defaults = d::parse_config("", "t.conf");
  EXPECT_EQ(defaults.settings.snap_trigger, d::SnapTrigger::kBoth);
  EXPECT_EQ(defaults.settings.hold_ms, 500);
  EXPECT_EQ(defaults.settings.hold_radius_mm, 1.0);
  const d::DaemonConfig c = d::parse_config(
      "snap_trigger = \"hold\"\nhold_ms = 800\nhold_radius_mm = 0.4\n[device.\"056a:0010\"]\n"
      "snap_trigger = \"pen_up\"\n",
      "t.conf");
  EXPECT_EQ(c.settings.snap_trigger, d::SnapTrigger::kHold);
  EXPECT_EQ(c.settings.hold_ms, 800);
  EXPECT_EQ(c.settings.hold_radius_mm, 0.4);
  EXPECT_EQ(c.device_settings.at("056a:0010").snap_trigger, d::SnapTrigger::kPenUp);
  for (const std::string bad :
       {"snap_trigger = \"sometimes\"", "hold_ms = 20", "hold_radius_mm = 0"}) {
    SCOPED_TRACE(bad);
    try {
      (void)d::parse_config(bad + "\n", "t.conf");
      ADD_FAILURE() << "accepted";
    } catch (const d::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(bad.substr(0, bad.find(' '))), std::string::npos)
          << e.what();
    }
  }
}

TEST(HoldConfig, ProtoFieldsAreCheckedAndNamed) {
  v1::PenSettings m;
  m.set_snap_trigger(v1::SNAP_TRIGGER_HOLD);
  m.set_hold_ms(700);
  m.set_hold_radius_mm(0.5);
  const d::PenSettingsUpdate u = d::settings_update_from_proto(m, "settings");
  EXPECT_EQ(u.snap_trigger, d::SnapTrigger::kHold);
  EXPECT_EQ(u.hold_ms, 700);
  EXPECT_EQ(u.hold_radius_mm, 0.5);
  auto message_of = [](const v1::PenSettings& bad) {
    try {
      (void)d::settings_update_from_proto(bad, "settings");
    } catch (const d::FieldError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  v1::PenSettings bad;
  bad.set_snap_trigger(v1::SNAP_TRIGGER_UNSPECIFIED);
  EXPECT_NE(message_of(bad).find("settings.snap_trigger"), std::string::npos);
  bad.Clear();
  bad.set_hold_ms(0);
  EXPECT_NE(message_of(bad).find("settings.hold_ms"), std::string::npos);
  bad.Clear();
  bad.set_hold_radius_mm(std::nan(""));
  EXPECT_NE(message_of(bad).find("settings.hold_radius_mm"), std::string::npos);
  v1::PenSettings out;
  d::to_proto(d::PenSettings{}, &out);
  EXPECT_EQ(out.snap_trigger(), v1::SNAP_TRIGGER_BOTH);
  EXPECT_EQ(out.hold_ms(), 500U);
}

} // namespace
