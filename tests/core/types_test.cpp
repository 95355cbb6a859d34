#include <gtest/gtest.h>

#include "penshape/core/version.hpp"
#include "penshape/types/stroke.hpp"

namespace penshape {
namespace {

TEST(TabletInfo, PhysicalSizeFromResolution) {
  TabletInfo t;
  t.x_max = 21600;
  t.y_max = 13500;
  t.x_resolution = 100.0;
  t.y_resolution = 100.0;
  EXPECT_DOUBLE_EQ(t.width_mm(), 216.0);
  EXPECT_DOUBLE_EQ(t.height_mm(), 135.0);
  t.x_resolution = 0.0; // unknown resolution: no size rather than a division by zero
  EXPECT_EQ(t.width_mm(), 0.0);
}

TEST(Stroke, Duration) {
  Stroke s;
  EXPECT_TRUE(s.empty());
  EXPECT_EQ(s.duration_us(), 0);
  s.samples.push_back({.time_us = 1000, .x = 1, .y = 2, .tip = true});
  EXPECT_EQ(s.duration_us(), 0);
  s.samples.push_back({.time_us = 9000, .x = 3, .y = 4});
  EXPECT_EQ(s.duration_us(), 8000);
  EXPECT_NE(s.samples[0], s.samples[1]);
}

TEST(Version, NamesTheGeometryLibraries) {
  EXPECT_FALSE(version().empty());
  const auto libs = geometry_library_versions();
  ASSERT_EQ(libs.size(), 2U);
  EXPECT_EQ(libs[0].rfind("CGAL 5.", 0), 0U) << libs[0];
  EXPECT_EQ(libs[1].rfind("GMP 6.", 0), 0U) << libs[1];
}

} // namespace
} // namespace penshape
