// Calligraphy outlines read back as pen paths (clients/snap/outline_centerline.hpp), on outlines
// built here from a known centre line and radius.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "snap/outline_centerline.hpp"

namespace penshape::snap {
namespace {

// The outline of a stroke along the x axis from 0 to len with radius r, as Inkscape's
// Calligraphy tool draws it: one edge forward from the start, a round cap, the other edge back,
// a round cap.
std::vector<PointD> straight_outline(double len, double r) {
  std::vector<PointD> ring;
  for (int i = 0; i <= 40; ++i) ring.push_back({len * i / 40.0, r});
  for (int i = 1; i < 16; ++i) {
    const double a = std::numbers::pi / 2 - std::numbers::pi * i / 16.0;
    ring.push_back({len + r * std::cos(a), r * std::sin(a)});
  }
  for (int i = 40; i >= 0; --i) ring.push_back({len * i / 40.0, -r});
  for (int i = 1; i < 16; ++i) {
    const double a = -std::numbers::pi / 2 - std::numbers::pi * i / 16.0;
    ring.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return ring;
}

TEST(OutlineCenterline, RadiusAndPathOfAStraightStroke) {
  const double len = 100, r = 3;
  const auto c = outline_centerline(straight_outline(len, r));
  ASSERT_TRUE(c.has_value());
  // A = 2 r L + pi r^2 and P = 2 L + 2 pi r hold up to the caps' polygonal approximation.
  EXPECT_NEAR(c->radius, r, 0.05);
  double min_x = 1e9, max_x = -1e9;
  for (const PointD& p : c->points) {
    EXPECT_NEAR(p.y, 0.0, r / 6) << p.x; // the ends pair cap points a polygon step apart
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
  }
  EXPECT_LT(min_x, 1.0);
  EXPECT_GT(max_x, len - 1.0);
}

TEST(OutlineCenterline, BlobsAndTinyRingsAreNoStrokes) {
  EXPECT_FALSE(outline_centerline({{0, 0}, {1, 0}, {0, 1}}).has_value());
  // A disk: P^2 = 4 pi A exactly for a circle, less for its inscribed polygon: no real root.
  std::vector<PointD> disk;
  disk.reserve(64);
  for (int i = 0; i < 64; ++i) {
    disk.push_back(
        {10 * std::cos(i * std::numbers::pi / 32), 10 * std::sin(i * std::numbers::pi / 32)});
  }
  const auto c = outline_centerline(disk);
  if (c) {
    EXPECT_GT(c->radius, 5.0) << "a disk is at best a dot of its own radius";
  }
}

} // namespace
} // namespace penshape::snap
