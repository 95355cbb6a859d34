// The raw offset path's spoke pruning (engine/fast/raw_offset.hpp): spokes dropped as covered
// leave the path's positive-winding region unchanged (winding numbers counted here at points
// away from every path edge), and the covering test itself on corners built by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "engine/fast/raw_offset.hpp"

namespace {

namespace cl = ClipperLib;
using penshape::fast::IPt;
using penshape::fast::IRing;
using penshape::fast::IRings;
using penshape::fast::raw_outward;
using penshape::fast::spoke_is_covered;
using penshape::fast::Spokes;

// Winding number of the closed paths around (x, y) (a point on no path edge).
int winding(const cl::Paths& paths, double x, double y) {
  int w = 0;
  for (const cl::Path& path : paths) {
    for (std::size_t i = 0; i < path.size(); ++i) {
      const cl::IntPoint& a = path[i];
      const cl::IntPoint& b = path[(i + 1) % path.size()];
      const double ax = static_cast<double>(a.X), ay = static_cast<double>(a.Y);
      const double bx = static_cast<double>(b.X), by = static_cast<double>(b.Y);
      const double cross = (bx - ax) * (y - ay) - (x - ax) * (by - ay);
      if (ay <= y && by > y && cross > 0) ++w;
      if (by <= y && ay > y && cross < 0) --w;
    }
  }
  return w;
}

double distance_to_paths(const cl::Paths& paths, double x, double y) {
  double best = INFINITY;
  for (const cl::Path& path : paths) {
    for (std::size_t i = 0; i < path.size(); ++i) {
      const cl::IntPoint& a = path[i];
      const cl::IntPoint& b = path[(i + 1) % path.size()];
      const double ax = static_cast<double>(a.X), ay = static_cast<double>(a.Y);
      const double dx = static_cast<double>(b.X) - ax, dy = static_cast<double>(b.Y) - ay;
      const double len2 = dx * dx + dy * dy;
      const double t =
          len2 > 0 ? std::fmax(0.0, std::fmin(1.0, ((x - ax) * dx + (y - ay) * dy) / len2)) : 0.0;
      best = std::fmin(best, std::hypot(x - ax - t * dx, y - ay - t * dy));
    }
  }
  return best;
}

std::size_t vertices(const cl::Paths& paths) {
  std::size_t n = 0;
  for (const cl::Path& p : paths) n += p.size();
  return n;
}

// A star-shaped (hence simple) counterclockwise ring with jagged radii: many reflex corners,
// edges from a few units to longer than the offset distance.
IRing jagged_star(std::mt19937& rng, int n, double r0, double r1) {
  std::uniform_real_distribution<double> radius(r0, r1);
  IRing ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    const double r = radius(rng);
    ring.push_back({std::llround(r * std::cos(a)), std::llround(r * std::sin(a))});
  }
  return ring;
}

// The positive regions of the two path sets agree at every grid point of [lo, hi]^2 at least 1.5
// units from both (the spokes' triangles are full of such points).
void expect_same_positive_region(const cl::Paths& a, const cl::Paths& b, int step, int lo = -1200,
                                 int hi = 1200) {
  int checked = 0;
  for (int x = lo; x <= hi; x += step) {
    for (int y = lo; y <= hi; y += step) {
      const double px = x + 0.25, py = y + 0.375;
      if (distance_to_paths(a, px, py) < 1.5 || distance_to_paths(b, px, py) < 1.5) continue;
      ASSERT_EQ(winding(a, px, py) > 0, winding(b, px, py) > 0) << "at " << px << ", " << py;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(RawOffsetSpokes, CoveredSpokesKeepThePositiveRegion) {
  std::mt19937 rng(26);
  std::size_t dropped = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const IRings rings{jagged_star(rng, 40 + 4 * trial, 300.0, 700.0)};
    for (const double delta : {40.0, 120.0, 300.0}) {
      const cl::Paths keep = raw_outward(rings, delta, delta / 8.0, Spokes::kKeep);
      const cl::Paths covered = raw_outward(rings, delta, delta / 8.0, Spokes::kCovered);
      dropped += vertices(keep) - vertices(covered);
      expect_same_positive_region(keep, covered, 29);
    }
  }
  EXPECT_GT(dropped, 20U); // the test exercises dropped spokes
}

// A square with a narrow V-shaped notch: its tip turns by about 160 degrees, where only one
// edge's quadrilateral covers most of the spoke's triangle. A path without that spoke loses a
// sliver of the offset along it, so this case fails if the covering test accepts it.
TEST(RawOffsetSpokes, SharpNotchKeepsItsSpoke) {
  const IRings rings{
      {{0, 0}, {1000, 0}, {1000, 1000}, {600, 1000}, {500, 400}, {400, 1000}, {0, 1000}}};
  for (const double delta : {60.0, 100.0, 150.0}) {
    const cl::Paths keep = raw_outward(rings, delta, delta / 8.0, Spokes::kKeep);
    expect_same_positive_region(keep, raw_outward(rings, delta, delta / 8.0, Spokes::kCovered), 7,
                                300, 700);
    expect_same_positive_region(keep, raw_outward(rings, delta, delta / 8.0, Spokes::kNarrow), 7,
                                300, 700);
  }
}

TEST(RawOffsetSpokes, NarrowDropsMoreSpokesThanCovered) {
  std::mt19937 rng(7);
  const IRings rings{jagged_star(rng, 80, 300.0, 700.0)};
  const std::size_t covered = vertices(raw_outward(rings, 120.0, 15.0, Spokes::kCovered));
  const std::size_t narrow = vertices(raw_outward(rings, 120.0, 15.0, Spokes::kNarrow));
  const std::size_t keep = vertices(raw_outward(rings, 120.0, 15.0, Spokes::kKeep));
  EXPECT_LT(narrow, covered);
  EXPECT_LE(covered, keep);
}

// A reflex corner turning right by 90 degrees at v = (0, 0): edge u -> v along +x (right
// normal (0, -1)), edge v -> w along -y (right normal (-1, 0)), offset by d. The edges'
// quadrilaterals hold the triangle (v, a, b) only when both edges are at least d long.
TEST(RawOffsetSpokes, CoveringNeedsEdgesAsLongAsTheSpoke) {
  const auto corner = [](std::int64_t len, std::int64_t d) {
    const IPt u{-len, 0}, v{0, 0}, w{0, -len};
    const IPt s{-len, -d}, a{0, -d}; // the first edge's offset: from s to a
    const IPt b{-d, 0}, e{-d, -len}; // the second edge's offset: from b to e
    return spoke_is_covered(u, s, a, v, b, e, w);
  };
  EXPECT_TRUE(corner(100, 40));
  EXPECT_TRUE(corner(100, 100));
  EXPECT_FALSE(corner(30, 40)); // the edges are shorter than the spoke
}

} // namespace
