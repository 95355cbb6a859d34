// The proto library's one conversion of pen messages: every field round-trips, and tilt follows
// one rule (degrees, clamped to ±90) whatever a client sends.
#include <gtest/gtest.h>

#include <limits>

#include "penshape/proto/pen_types.hpp"

namespace penshape {
namespace {

PenSample full_sample() {
  PenSample s;
  s.time_us = 1'234'567'890'123;
  s.x = 40'000;
  s.y = 25'000;
  s.pressure = 8191;
  s.tilt_x = -37;
  s.tilt_y = 90;
  s.buttons = kBarrel1 | kEraser;
  s.in_range = true;
  s.tip = true;
  return s;
}

TEST(ProtoPenTypes, SampleRoundTripsEveryField) {
  v1::PenSample m;
  proto::to_proto(full_sample(), &m);
  EXPECT_EQ(proto::from_proto(m), full_sample());
}

TEST(ProtoPenTypes, TabletRoundTripsEveryField) {
  TabletInfo t;
  t.bus = Bus::kBluetooth;
  t.vendor_id = 0x056a;
  t.product_id = 0x0010;
  t.name = "Wacom Graphire";
  t.x_max = 10'206;
  t.y_max = 7'422;
  t.pressure_max = 511;
  t.x_resolution = 100.0;
  t.y_resolution = 100.0;
  t.has_tilt = true;
  v1::TabletInfo m;
  proto::to_proto(t, &m);
  EXPECT_EQ(proto::from_proto(m), t);
}

TEST(ProtoPenTypes, StrokeCarriesItsTabletAndSamples) {
  Stroke stroke;
  stroke.id = 7;
  stroke.tablet.name = "t";
  stroke.samples = {full_sample(), full_sample()};
  v1::Stroke m;
  proto::to_proto(stroke, &m);
  EXPECT_EQ(m.id(), 7U);
  EXPECT_EQ(m.tablet().name(), "t");
  ASSERT_EQ(m.samples_size(), 2);
  EXPECT_EQ(proto::from_proto(m.samples(1)), full_sample());
}

// types.proto says degrees: a pen lies at most flat, so |tilt| <= 90. Beyond that is clamped,
// never wrapped into int16 (65536 + 5 must not read as 5).
TEST(ProtoPenTypes, TiltIsClampedToNinetyDegrees) {
  const std::pair<int, int> cases[] = {{0, 0},
                                       {89, 89},
                                       {90, 90},
                                       {-90, -90},
                                       {91, 90},
                                       {-91, -90},
                                       {32'767, 90},
                                       {65'536 + 5, 90},
                                       {-40'000, -90},
                                       {std::numeric_limits<int>::max(), 90},
                                       {std::numeric_limits<int>::min(), -90}};
  for (const auto& [sent, read] : cases) {
    v1::PenSample m;
    m.set_tilt_x(sent);
    const PenSample s = proto::from_proto(m);
    EXPECT_EQ(s.tilt_x, read) << "tilt_x " << sent;
  }
  v1::PenSample m;
  m.set_tilt_y(-1000);
  EXPECT_EQ(proto::from_proto(m).tilt_y, -proto::kMaxTiltDegrees);
  m.set_tilt_y(1000);
  EXPECT_EQ(proto::from_proto(m).tilt_y, proto::kMaxTiltDegrees);
}

} // namespace
} // namespace penshape
