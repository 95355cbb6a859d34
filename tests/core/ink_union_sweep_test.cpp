// Clipper's sweep decisions in the ink polygon's unions (core/src/ink/ink_union.hpp), measured with
// exact arithmetic (exact_union.hpp, including the points of every edge on every scanline): cases
// where Clipper's union is farther from the exact union than the old per-union budget (half a grid
// diagonal plus the double arithmetic) stay within the new one (the sweep term, times the pieces'
// pinch factor); a piece thin enough to be pinched away whole is beyond any per-union term, which
// is why the ink polygon widens disks below the grid's scale. The ink bound counts the sweep.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "exact_union.hpp"
#include "ink/ink_union.hpp"
#include "penshape/core/ink.hpp"

namespace penshape {
namespace {

using ClipperLib::cInt;
using ClipperLib::Path;
using ClipperLib::Paths;

constexpr double kHalfDiagonal = std::numbers::sqrt2 / 2;

// The per-union budget before the sweep was counted.
double old_budget(double m) { return kHalfDiagonal + ink_detail::clipper_union_arithmetic(m); }

// The per-union budget now, without and with the pieces' pinch factor.
double sweep_budget(double m) { return old_budget(m) + ink_detail::clipper_union_sweep(m); }
double budget(const Paths& pieces, double m) {
  return ink_detail::clipper_pinch_factor(pieces) * sweep_budget(m);
}

Path oriented(Path p) {
  if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
  return p;
}

// An axis-parallel box far to the side: a scanline at y (its corners are right angles).
Path mark(cInt y) { return oriented({{100, y}, {105, y}, {105, y + 1}, {100, y + 1}}); }

// At y = -32 the triangle's sides round to the same x: the touching point cuts its apex off.
TEST(InkUnionSweep, TriangleApexCutAtAScanline) {
  const Paths pieces{oriented({{-1000, -26}, {-1005, -26}, {-1002, -32}}),
                     oriented({{-1023, -27}, {-1028, -27}, {-1025, -33}})};
  const double error = test::union_error_lower_bound(pieces, true);
  EXPECT_GT(error, old_budget(1028));
  EXPECT_LE(error, budget(pieces, 1028));
}

// A needle's last 400 units are thinner than half a unit at the scanline y = -600: pinched off,
// far beyond the sweep term, within it times the apex's 1 / sin.
TEST(InkUnionSweep, NeedleTipPinchedOffWithinItsCorner) {
  const Paths pieces{oriented({{0, 0}, {1, 0}, {0, -1000}}), mark(-600)};
  const double error = test::union_error_lower_bound(pieces, true);
  EXPECT_GT(error, 399.0);
  EXPECT_GT(error, sweep_budget(1000));
  EXPECT_LE(error, budget(pieces, 1000));
}

// A triangle half a unit thick at its middle vertex's scanline is pinched there on both sides and
// vanishes: no per-union term bounds that (the ink polygon's pieces are never this thin).
TEST(InkUnionSweep, ThinPieceVanishesWhole) {
  const Paths pieces{oriented({{5, 2}, {8, 4}, {6, 3}}), mark(7)};
  const double error = test::union_error_lower_bound(pieces, true);
  EXPECT_GT(error, 90.0);
  EXPECT_GT(error, budget(pieces, 105));
}

cInt uniform(std::mt19937_64& g, cInt lo, cInt hi) {
  return lo + static_cast<cInt>(g() % static_cast<std::uint64_t>(hi - lo + 1));
}

// A random triangle in a 13 x 13 box, each altitude at least 2 units (not pinched away whole).
Path fat_triangle(std::mt19937_64& g) {
  for (;;) {
    Path p;
    for (int i = 0; i < 3; ++i) p.push_back({uniform(g, 0, 12), uniform(g, 0, 12)});
    const double area2 = std::abs(ClipperLib::Area(p)) * 2;
    double longest = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      const double dx = static_cast<double>(p[i].X - p[(i + 1) % 3].X);
      const double dy = static_cast<double>(p[i].Y - p[(i + 1) % 3].Y);
      longest = std::max(longest, std::hypot(dx, dy));
    }
    if (area2 >= 2 * longest) return oriented(p);
  }
}

// Small triangles (sharp corners, sides meeting near grid points) with scanlines across them.
TEST(InkUnionSweep, SmallTrianglesStayWithinTheBound) {
  std::mt19937_64 g(5);
  int beyond_old = 0;
  double worst = 0;
  for (int t = 0; t < 1500; ++t) {
    Paths pieces;
    for (int k = 0; k <= t % 3; ++k) pieces.push_back(fat_triangle(g));
    for (int k = 0; k <= t % 4; ++k) pieces.push_back(mark(uniform(g, 0, 12)));
    const double error = test::union_error_lower_bound(pieces, true);
    if (error > old_budget(105)) ++beyond_old;
    worst = std::max(worst, error / budget(pieces, 105));
    ASSERT_LE(error, budget(pieces, 105)) << t;
  }
  EXPECT_GT(beyond_old, 0) << "the family never needs the sweep term";
  RecordProperty("beyond_old_budget", beyond_old);
  RecordProperty("worst_fraction_of_budget", std::to_string(worst));
}

// An offset stroke goes through two unions (its own and the final one), four roundings and two
// sweeps; the grid leaves room for them within max_error.
TEST(InkUnionSweep, InkBoundCountsTheSweepOfEachUnion) {
  std::vector<InkSample> stroke;
  stroke.reserve(30);
  for (int i = 0; i < 30; ++i) stroke.push_back({i * 0.7, std::sin(i * 0.3) * 5, 0.5});
  InkOptions options;
  options.radius_mm = 0.5;
  const double me = options.radius_mm / 50;
  const InkPolygon ink = ink_polygon(stroke, options);
  // Each sweep is at least a grid unit (two half units of TopX's rounding).
  const double grid_terms = 4 * kHalfDiagonal + 2 * 1.0;
  EXPECT_GE(ink.hausdorff_bound, me / 2 + me / 4 + grid_terms * ink.grid);
  EXPECT_LE(ink.hausdorff_bound, me);
}

// A disk far below the grid's scale would round to a point and vanish from the union (and a thin
// hull could be pinched away whole): it is drawn with four grid units, and the bound says so.
TEST(InkUnionSweep, TinyDisksAreWidenedNotLost) {
  const std::vector<std::vector<InkSample>> strokes{{{0, 0, 1.0}, {10, 0, 1.0}}, {{5, 20, 1e-6}}};
  InkOptions options;
  options.radius_mm = 1.0;
  const InkPolygon ink = ink_polygon(strokes, options);
  ASSERT_LT(1e-6, ink.grid);
  EXPECT_EQ(ink.region.polygons.size(), 2U) << "the dot is part of the ink";
  EXPECT_GE(ink.hausdorff_bound, 4 * ink.grid - 1e-6);
}

} // namespace
} // namespace penshape
