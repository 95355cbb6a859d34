// The ink certificate's pruned grid scan (core/src/recognize/certify/ink_certificate.cpp) against
// the flat scan that visits every grid point: the bound must be the same double, bit for bit, on
// every input (pruning only skips grid points proven unable to change either maximum). Random
// clean shapes of every kind (segments, polylines, polygons, circles, arcs, ellipses and
// elliptic arcs) against inks drawn along them, along a perturbed copy and along another shape;
// then the real $1 strokes of ../shared/data/strokes against shapes fitted roughly to them.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "penshape/core/ink.hpp"
#include "recognize/certify/ink_certificate.hpp"
#include "recognize/fitting/clean_shape.hpp"
#include "test_support.hpp"

namespace penshape {
namespace {

using recognize_detail::CleanShape;
using recognize_detail::InkScan;

// Both scans on one ink; returns the bound (the same from both, or the test fails).
double expect_same_bound(const InkPolygon& ink, const CleanShape& shape, double epsilon,
                         double pen_radius) {
  const recognize_detail::InkRegion q = recognize_detail::prepare_ink(ink, epsilon);
  const Certificate flat =
      recognize_detail::certify_ink(q, shape, epsilon, pen_radius, InkScan::kFlat);
  const Certificate pruned =
      recognize_detail::certify_ink(q, shape, epsilon, pen_radius, InkScan::kPruned);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(flat.bound), std::bit_cast<std::uint64_t>(pruned.bound))
      << "flat " << flat.bound << " pruned " << pruned.bound << " epsilon " << epsilon;
  EXPECT_EQ(flat.certified, pruned.certified);
  return flat.bound;
}

CleanShape random_shape(std::mt19937_64& rng, int kind) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  CleanShape s;
  const PointD c{5.0 * u(rng), 5.0 * u(rng)};
  const double size = 8.0 + 6.0 * u(rng);
  if (kind <= 2) { // segment, open polyline, closed polygon
    const int n = kind == 0 ? 2 : 3 + static_cast<int>(4.5 + 4.5 * u(rng));
    for (int k = 0; k < n; ++k) s.path.push_back({c.x + size * u(rng), c.y + size * u(rng)});
    if (kind == 2) s.path.push_back(s.path.front());
    return s;
  }
  s.kind = kind <= 4 ? CleanShape::Kind::kCircle : CleanShape::Kind::kEllipse;
  s.center = c;
  s.rx = size;
  s.ry = kind <= 4 ? size : size * (0.35 + 0.3 * (1.0 + u(rng)));
  s.rotation = kind <= 4 ? 0.0 : std::numbers::pi * u(rng);
  s.t0 = std::numbers::pi * u(rng);
  // Full curves for kinds 3 and 5; arcs (either direction) for 4 and 6.
  s.sweep = kind % 2 == 1 ? 2.0 * std::numbers::pi : std::numbers::pi * 1.6 * u(rng);
  if (std::abs(s.sweep) < 0.3) s.sweep = 0.3;
  return s;
}

// The ink of samples along `path`, each displaced by up to `wobble` and with a radius varying
// like pressure around `radius`.
InkPolygon ink_along(const std::vector<PointD>& path, double wobble, double radius,
                     std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<InkSample> samples;
  samples.reserve(path.size());
  for (const PointD& p : path) {
    samples.push_back(
        {p.x + wobble * u(rng), p.y + wobble * u(rng), radius * (1.0 + 0.3 * u(rng))});
  }
  InkOptions options;
  options.radius_mm = radius;
  return ink_polygon(samples, options);
}

TEST(InkCertificatePruned, SameBoundAsTheFlatScanOnGeneratedShapes) {
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int certified = 0, total = 0;
  for (int trial = 0; trial < 140; ++trial) {
    const CleanShape shape = random_shape(rng, trial % 7);
    // The ink along the shape itself (certifies), a wobbly copy (near the tolerance), or along
    // another shape (far off: large bounds, some beyond the box rule).
    const int mode = (trial / 7) % 3;
    const CleanShape other = mode == 2 ? random_shape(rng, (trial + 3) % 7) : shape;
    const double wobble = mode == 0 ? 0.02 : 0.4 + u(rng);
    // Every other trial a broad ink (many grid points deep inside it, far from its edges).
    const double radius = trial % 2 == 0 ? 0.4 + 0.4 * u(rng) : 1.5 + 1.5 * u(rng);
    const InkPolygon ink = ink_along(other.sample(0.3), wobble, radius, rng);
    const double epsilon = 0.8 + 2.0 * u(rng);
    const double pen = 0.3 + 0.5 * u(rng);
    certified += expect_same_bound(ink, shape, epsilon, pen) <= epsilon ? 1 : 0;
    ++total;
  }
  // Not vacuous: some certify, some do not.
  EXPECT_GT(certified, 0);
  EXPECT_LT(certified, total);
}

// A broad blot of ink inside curves and polygons around it: the Q side's maximum lies deep
// inside Q, far from its edges (where only the parity selects grid points).
TEST(InkCertificatePruned, SameBoundWhenTheMaximumIsDeepInsideTheInk) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 28; ++trial) {
    CleanShape shape = random_shape(rng, trial % 7);
    const PointD c = shape.kind == CleanShape::Kind::kPolyline ? shape.path.front() : shape.center;
    const double size = shape.kind == CleanShape::Kind::kPolyline ? 6.0 : shape.rx;
    const InkPolygon ink = ink_along({{c.x - 0.2, c.y}, {c.x + 0.2, c.y}}, 0.0, 0.5 * size, rng);
    expect_same_bound(ink, shape, 1.2 * size, 0.3);
  }
}

// Real strokes (every 12th $1 gesture): an ink with varying radius along the logged points,
// against the chord from first to last point, the polyline of every 8th point, the circle and
// the ellipse of the stroke's box, and an arc of that circle.
TEST(InkCertificatePruned, SameBoundAsTheFlatScanOnRealStrokes) {
  PENSHAPE_SHARED_OR_SKIP(dir, "strokes/dollar1");
  std::mt19937_64 rng(7);
  const std::vector<test::Gesture> gestures = test::all_dollar_gestures();
  ASSERT_FALSE(gestures.empty());
  for (std::size_t g = 0; g < gestures.size(); g += 12) {
    std::vector<PointD> path;
    for (const StrokePoint& p : gestures[g].points) path.push_back({p.x, p.y});
    if (path.size() < 2) continue;
    PointD lo = path[0], hi = path[0];
    for (const PointD& p : path) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    const double size = std::max({hi.x - lo.x, hi.y - lo.y, 1.0});
    const InkPolygon ink = ink_along(path, 0.0, size / 60.0, rng);
    std::vector<CleanShape> shapes(5);
    shapes[0].path = {path.front(), path.back()};
    for (std::size_t k = 0; k < path.size(); k += 8) shapes[1].path.push_back(path[k]);
    shapes[1].path.push_back(path.back());
    for (std::size_t k = 2; k < 5; ++k) {
      shapes[k].kind = k == 3 ? CleanShape::Kind::kEllipse : CleanShape::Kind::kCircle;
      shapes[k].center = {0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y)};
      shapes[k].rx = k == 3 ? 0.5 * (hi.x - lo.x) + 0.01 : 0.25 * (hi.x - lo.x + hi.y - lo.y);
      shapes[k].ry = k == 3 ? 0.5 * (hi.y - lo.y) + 0.01 : shapes[k].rx;
    }
    shapes[4].t0 = 0.5;
    shapes[4].sweep = -3.5;
    for (const CleanShape& s : shapes) {
      expect_same_bound(ink, s, size / 8.0, size / 60.0);
      if (::testing::Test::HasFailure()) return; // one stroke's report is enough
    }
  }
}

} // namespace
} // namespace penshape
