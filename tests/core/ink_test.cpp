// Ink polygons: valid regions within their stated error of the exact swept region, checked
// independently (point-to-segment distances in doubles, no Clipper, no CGAL).
#include "penshape/core/ink.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "drawn_points.hpp"
#include "penshape/core/deconstruct.hpp"
#include "support/dollar1.hpp"
#include "support/hausdorff_check.hpp"
#include "test_data.hpp"

namespace penshape {
namespace {

std::vector<InkSample> with_radius(const std::vector<PointD>& pts, double r) {
  std::vector<InkSample> out;
  out.reserve(pts.size());
  for (const auto& p : pts) out.push_back({p.x, p.y, r});
  return out;
}

double distance_to_polyline(const std::vector<PointD>& pts, PointD p) {
  double best = std::hypot(p.x - pts[0].x, p.y - pts[0].y);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const PointD a = pts[i];
    const PointD b = pts[i + 1];
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    const double t =
        len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy));
  }
  return best;
}

// Every point of ∂Q (sampled densely) is at distance r ± bound from the stroke, Q is a valid
// region, and the sampled Hausdorff distance to the exact offset is within bound.
void expect_ink_close(const std::vector<PointD>& pts, double r, const InkPolygon& ink,
                      double grid_spacing) {
  ASSERT_FALSE(ink.region.empty());
  EXPECT_NO_THROW(validate_region(ink.region));
  EXPECT_LE(ink.hausdorff_bound, r / 50 + 1e-12); // the default max_error
  const double tiny = 1e-9;
  for (const auto& ring : test::to_region_d(ink.region).rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const PointD a = ring[i];
      const PointD b = ring[(i + 1) % ring.size()];
      for (int s = 0; s < 8; ++s) {
        const double t = s / 8.0;
        const PointD p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        const double d = distance_to_polyline(pts, p);
        ASSERT_NEAR(d, r, ink.hausdorff_bound + tiny) << "boundary point " << p.x << ", " << p.y;
      }
    }
  }
  test::SkeletonD skeleton;
  skeleton.polylines.push_back(pts);
  const auto h =
      test::hausdorff_to_offset(skeleton, r, test::to_region_d(ink.region), grid_spacing);
  EXPECT_LE(h.value, ink.hausdorff_bound + h.error + tiny);
}

TEST(InkPolygon, SinglePointIsADisk) {
  const std::vector<PointD> pts{{10, 20}};
  const InkPolygon ink = ink_polygon(with_radius(pts, 2.0), {.radius_mm = 2.0});
  ASSERT_EQ(ink.region.polygons.size(), 1U);
  EXPECT_TRUE(ink.region.polygons[0].holes.empty());
  const double a = to_double(area(ink.region));
  EXPECT_NEAR(a, std::numbers::pi * 4, std::numbers::pi * 4 * 0.02);
  expect_ink_close(pts, 2.0, ink, 0.05);
}

// The bound at its edge: a lone disk's polygon reaches in by its sagitta at every chord's
// midpoint, so its worst deviation from the circle comes within the terms a disk does not use
// (simplification tau, the grid) of the stated bound, and never beyond it.
TEST(InkPolygon, DiskBoundIsReachedAndNeverExceeded) {
  for (const double r : {0.5, 2.0, 37.0}) {
    SCOPED_TRACE(r);
    const InkPolygon ink = ink_polygon(with_radius({{3, -4}}, r), {.radius_mm = r});
    double worst = 0;
    for (const auto& ring : test::to_region_d(ink.region).rings) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const PointD a = ring[i], b = ring[(i + 1) % ring.size()];
        for (int s = 0; s <= 16; ++s) {
          const double t = s / 16.0;
          const double d = std::hypot(a.x + t * (b.x - a.x) - 3, a.y + t * (b.y - a.y) + 4);
          worst = std::max(worst, std::abs(d - r));
        }
      }
    }
    const double tau = r / 50 / 4; // the default max_error is r / 50, a quarter for simplifying
    EXPECT_LE(worst, ink.hausdorff_bound);
    EXPECT_GE(worst, ink.hausdorff_bound - tau - 3 * std::numbers::sqrt2 * ink.grid);
  }
}

TEST(InkPolygon, ClosedLoopEnclosesAHole) {
  std::vector<PointD> pts;
  for (int i = 0; i <= 64; ++i) {
    const double a = 2 * std::numbers::pi * i / 64;
    pts.push_back({50 + 20 * std::cos(a), 50 + 20 * std::sin(a)});
  }
  const InkPolygon ink = ink_polygon(with_radius(pts, 1.5), {.radius_mm = 1.5});
  ASSERT_EQ(ink.region.polygons.size(), 1U);
  EXPECT_EQ(ink.region.polygons[0].holes.size(), 1U);
  expect_ink_close(pts, 1.5, ink, 0.25);
}

TEST(InkPolygon, DoublingBackAndSelfCrossing) {
  // Out and back along the x axis, then a figure-eight through (20, 0): one component with three
  // holes (the two loops of the eight, and the triangle (10,0), (10,10), (20,0) closed off by
  // the axis).
  const std::vector<PointD> pts{{0, 0},  {30, 0},   {10, 0},   {10, 10},  {20, 20}, {30, 10},
                                {20, 0}, {10, -10}, {20, -20}, {30, -10}, {20, 0},  {10, 10}};
  const InkPolygon ink = ink_polygon(with_radius(pts, 1.0), {.radius_mm = 1.0});
  ASSERT_EQ(ink.region.polygons.size(), 1U);
  EXPECT_EQ(ink.region.polygons[0].holes.size(), 3U);
  expect_ink_close(pts, 1.0, ink, 0.2);
}

void expect_valid_and_close(const std::vector<PointD>& pts) {
  const double r = 3.0; // pixels as millimetres (resolution unknown)
  const InkPolygon ink = ink_polygon(with_radius(pts, r), {.radius_mm = r});
  expect_ink_close(pts, r, ink, 0.75);
}

TEST(InkPolygon, RealStrokesAreValidAndClose) {
  PENSHAPE_SHARED_OR_SKIP(dir, "strokes/dollar1/s02/medium");
  for (const char* name : {"circle01.xml", "rectangle01.xml", "star01.xml", "pigtail01.xml",
                           "x01.xml", "question_mark01.xml"}) {
    SCOPED_TRACE(name);
    expect_valid_and_close(test::read_dollar1((dir / name).string()));
  }
}

TEST(InkPolygon, GeneratedStrokesAreValidAndClose) {
  for (const char* kind : {"circle", "rectangle", "arrow1", "scribble", "word", "spiral", "dot"}) {
    SCOPED_TRACE(kind);
    expect_valid_and_close(gen::drawn_points(6, kind));
  }
}

TEST(InkPolygon, StrokeInDeviceUnitsUsesTheResolution) {
  Stroke stroke;
  stroke.tablet.x_resolution = 100; // units per mm
  stroke.tablet.y_resolution = 50;
  stroke.tablet.pressure_max = 1000;
  stroke.samples = {{.x = 1000, .y = 1000, .pressure = 1000},
                    {.x = 3000, .y = 1000, .pressure = 0}};
  const auto samples = ink_samples(
      stroke, {.radius_mm = 1.0, .use_pressure = true, .min_fraction = 0.5, .gamma = 1.0});
  ASSERT_EQ(samples.size(), 2U);
  EXPECT_DOUBLE_EQ(samples[0].x, 10.0);
  EXPECT_DOUBLE_EQ(samples[0].y, 20.0);
  EXPECT_DOUBLE_EQ(samples[1].x, 30.0);
  EXPECT_DOUBLE_EQ(samples[0].radius, 1.0); // full pressure: full radius
  EXPECT_DOUBLE_EQ(samples[1].radius, 0.5); // no pressure: min_fraction
  const InkPolygon ink =
      ink_polygon(stroke, {.radius_mm = 1.0, .use_pressure = true, .min_fraction = 0.5});
  EXPECT_NO_THROW(validate_region(ink.region));
  // A tapered capsule: area between the two constant-radius capsules.
  const double a = to_double(area(ink.region));
  EXPECT_GT(a, 20 * 1.0 + std::numbers::pi * 0.25 * 0.98);
  EXPECT_LT(a, 20 * 2.0 + std::numbers::pi);
}

TEST(InkPolygon, BadInputIsRejected) {
  EXPECT_THROW(ink_polygon(std::vector<InkSample>{}, {}), InvalidInput);
  EXPECT_THROW(ink_polygon(std::vector<InkSample>{{0, 0, 1}}, {.radius_mm = -1}), InvalidInput);
  EXPECT_THROW(ink_polygon(std::vector<InkSample>{{std::nan(""), 0, 1}}, {}), InvalidInput);
  EXPECT_THROW(ink_polygon(std::vector<InkSample>{{0, 0, 1}, {1e12, 0, 1}}, {}), InvalidInput);
  EXPECT_THROW(
      ink_polygon(std::vector<InkSample>{{0, 0, 1}}, {.radius_mm = 1, .max_error_mm = 1e-30}),
      InvalidInput);
}

} // namespace
} // namespace penshape

namespace penshape {
namespace {

TEST(InkPolygon, SeveralStrokesGiveSeveralComponents) {
  // The two strokes of a "=" sign, and a third crossing neither: three components.
  const std::vector<std::vector<PointD>> strokes{
      {{0, 0}, {20, 0}}, {{0, 10}, {20, 10}}, {{40, 0}, {40, 10}, {45, 12}}};
  std::vector<std::vector<InkSample>> samples;
  samples.reserve(strokes.size());
  for (const auto& s : strokes) samples.push_back(with_radius(s, 1.0));
  const InkPolygon ink = ink_polygon(samples, {.radius_mm = 1.0});
  EXPECT_EQ(ink.region.polygons.size(), 3U);
  EXPECT_NO_THROW(validate_region(ink.region));
  // Every stroke's own ink lies within the union's error of the union.
  for (const auto& s : strokes) {
    const InkPolygon one = ink_polygon(with_radius(s, 1.0), {.radius_mm = 1.0});
    EXPECT_GE(to_double(area(ink.region)), to_double(area(one.region)) * 0.999);
  }
}

// The grid roundings counted in the bound (issue #22): one stroke offset by Clipper is rounded
// three times (input, offset vertices, the offset's own union), a union of crossing strokes a
// fourth time (the union's intersections). Each counts half a grid diagonal, on top of the
// disk's max_error / 2 and the simplification's max_error / 4; the total stays <= max_error.
TEST(InkPolygon, BoundCountsEveryGridRounding) {
  const double me = 0.02; // the default max_error for radius 1
  const std::vector<PointD> a{{0, 0}, {20, 3}, {40, 0}}, b{{10, -10}, {12, 10}};
  const InkPolygon one = ink_polygon(with_radius(a, 1.0), {.radius_mm = 1.0});
  const InkPolygon both =
      ink_polygon(std::vector{with_radius(a, 1.0), with_radius(b, 1.0)}, {.radius_mm = 1.0});
  ASSERT_EQ(both.region.polygons.size(), 1U); // they cross
  const double half_diagonal = std::numbers::sqrt2 / 2;
  EXPECT_GE(one.hausdorff_bound, me / 2 + me / 4 + 3 * half_diagonal * one.grid);
  EXPECT_GE(both.hausdorff_bound, me / 2 + me / 4 + 4 * half_diagonal * both.grid);
  EXPECT_LE(one.hausdorff_bound, me);
  EXPECT_LE(both.hausdorff_bound, me);
}

// Signed distance to the region swept by disks of linearly varying radius: the union over t of
// D_{r(t)}(p(t)) is exactly the hull of the end disks, and |y - p(t)| - r(t) is convex in t, so
// a ternary search finds its minimum per segment.
double swept_signed_distance(const std::vector<InkSample>& s, PointD y) {
  auto f = [&](const InkSample& a, const InkSample& b, double t) {
    return std::hypot(y.x - (a.x + t * (b.x - a.x)), y.y - (a.y + t * (b.y - a.y))) -
           (a.radius + t * (b.radius - a.radius));
  };
  double best = f(s[0], s[0], 0.0);
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    double lo = 0, hi = 1;
    for (int it = 0; it < 100; ++it) {
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      if (f(s[i], s[i + 1], m1) < f(s[i], s[i + 1], m2)) {
        hi = m2;
      } else {
        lo = m1;
      }
    }
    best = std::min(best, f(s[i], s[i + 1], (lo + hi) / 2));
  }
  return best;
}

// A stroke with a pressure ramp: Q lies between the ink of the thinnest and of the thickest
// constant pen (areas), and is a valid region.
void expect_pressure_ink_within_radii(const std::vector<PointD>& pts) {
  std::vector<InkSample> samples;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(pts.size() - 1);
    samples.push_back({pts[i].x, pts[i].y, 1.0 + 2.0 * t});
  }
  const InkPolygon ink = ink_polygon(samples, {.radius_mm = 3.0});
  EXPECT_NO_THROW(validate_region(ink.region));
  const double a = to_double(area(ink.region));
  const double thin =
      to_double(area(ink_polygon(with_radius(pts, 1.0), {.radius_mm = 1.0}).region));
  const double thick =
      to_double(area(ink_polygon(with_radius(pts, 3.0), {.radius_mm = 3.0}).region));
  EXPECT_GT(a, thin);
  EXPECT_LT(a, thick);
  // Every boundary vertex of Q lies on the exact swept boundary, up to the stated error.
  for (const auto& ring : test::to_region_d(ink.region).rings) {
    for (const PointD& v : ring) {
      ASSERT_NEAR(swept_signed_distance(samples, v), 0.0, ink.hausdorff_bound + 1e-9)
          << v.x << ", " << v.y;
    }
  }
}

TEST(InkPolygon, PressureStrokeIsValidAndWithinItsRadii) {
  PENSHAPE_SHARED_OR_SKIP(file, "strokes/dollar1/s02/medium/pigtail01.xml");
  expect_pressure_ink_within_radii(test::read_dollar1(file.string()));
}

TEST(InkPolygon, GeneratedPressureStrokeIsValidAndWithinItsRadii) {
  expect_pressure_ink_within_radii(gen::drawn_points(8, "spiral"));
}

} // namespace
} // namespace penshape

namespace penshape {
namespace {

// The daemon's path: stroke → ink polygon → decision with the pen radius; every YES is checked
// independently against the ink polygon. True on YES.
bool expect_ink_deconstructs(const std::vector<PointD>& pts) {
  {
    const double r = 3.0;
    const InkPolygon ink = ink_polygon(with_radius(pts, r), {.radius_mm = r});
    const DeconstructParams params{Rational(3), Rational(3, 2), Rational(3, 16),
                                   EngineKind::kReference};
    const auto res = deconstruct(ink.region, params);
    if (res.answer != Answer::kYes) return false;
    const auto h = test::hausdorff_to_offset(test::region_skeleton(res.solution), r,
                                             test::to_region_d(ink.region), 0.5);
    EXPECT_LE(h.value, 1.5 + h.error + 1e-9);
    return true;
  }
}

TEST(InkPolygon, RealStrokeInkDeconstructs) {
  PENSHAPE_SHARED_OR_SKIP(dir, "strokes/dollar1/s03/medium");
  int yes = 0;
  for (const char* name : {"circle02.xml", "triangle02.xml", "v02.xml"}) {
    SCOPED_TRACE(name);
    yes += expect_ink_deconstructs(test::read_dollar1((dir / name).string())) ? 1 : 0;
  }
  EXPECT_GE(yes, 1);
}

TEST(InkPolygon, GeneratedStrokeInkDeconstructs) {
  int yes = 0;
  for (const char* kind : {"circle", "triangle", "line"}) {
    SCOPED_TRACE(kind);
    yes += expect_ink_deconstructs(gen::drawn_points(10, kind)) ? 1 : 0;
  }
  EXPECT_GE(yes, 1);
}

} // namespace
} // namespace penshape
