#include <gtest/gtest.h>

#include "penshape/v1/types.pb.h"

namespace {

TEST(Proto, StrokeRoundTrip) {
  penshape::v1::Stroke stroke;
  stroke.set_id(42);
  stroke.mutable_tablet()->set_vendor_id(0x056a);
  stroke.mutable_tablet()->set_bus(penshape::v1::BUS_USB);
  stroke.mutable_tablet()->set_x_resolution(100.0);
  for (int i = 0; i < 3; ++i) {
    auto* s = stroke.add_samples();
    s->set_time_us(std::int64_t{1000} * i);
    s->set_x(10 * i);
    s->set_y(-5 * i);
    s->set_tip(i < 2);
  }
  const std::string bytes = stroke.SerializeAsString();
  penshape::v1::Stroke back;
  ASSERT_TRUE(back.ParseFromString(bytes));
  EXPECT_EQ(back.id(), 42U);
  EXPECT_EQ(back.tablet().vendor_id(), 0x056aU);
  EXPECT_EQ(back.tablet().bus(), penshape::v1::BUS_USB);
  ASSERT_EQ(back.samples_size(), 3);
  EXPECT_EQ(back.samples(2).y(), -10);
  EXPECT_FALSE(back.samples(2).tip());
}

TEST(Proto, TruncatedBytesAreRejected) {
  penshape::v1::PolygonSet set;
  auto* ring = set.add_polygons()->mutable_outer();
  for (int i = 0; i < 4; ++i) {
    auto* p = ring->add_points();
    p->set_x(i);
    p->set_y(i * i);
  }
  const std::string bytes = set.SerializeAsString();
  penshape::v1::PolygonSet back;
  EXPECT_FALSE(back.ParseFromString(bytes.substr(0, bytes.size() - 3)));
}

} // namespace
