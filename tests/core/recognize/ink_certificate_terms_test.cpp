// Two terms of the ink certificate (core/src/recognize/certify/ink_certificate.cpp) that issue #22
// found short, each against a worst case computed here: the grid's reach (the half-diagonal of the
// widest cell of the double grid o + (i h, j h)) against the exact widest gaps, on grids where
// the coordinates' rounding widens a gap by more than the old allowance; and the arc's rounded
// end parameter on the ink-to-shape side, on an arc whose end rounds half a turn's ulp beyond
// the true end.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "penshape/core/ink.hpp"
#include "penshape/core/ink_certificate.hpp"
#include "recognize/certify/ink_certificate.hpp"

namespace penshape {
namespace {

// The widest gap between consecutive lines, exactly.
Rational widest_gap(const std::vector<double>& lines) {
  Rational widest(0);
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const Rational gap = Rational(lines[k]) - Rational(lines[k - 1]);
    if (gap > widest) widest = gap;
  }
  return widest;
}

// The lines are the grid's doubles, cover the box, and reach^2 >= (A^2 + B^2) / 4 exactly.
void check_reach(PointD origin, double h, PointD lo, PointD hi) {
  const recognize_detail::GridLines g = recognize_detail::grid_lines(origin, h, lo, hi);
  ASSERT_GE(g.x.size(), 2U);
  ASSERT_GE(g.y.size(), 2U);
  for (std::size_t k = 0; k < g.x.size(); ++k) {
    ASSERT_EQ(g.x[k], origin.x + static_cast<double>(g.first_i + static_cast<std::int64_t>(k)) * h);
  }
  for (std::size_t k = 0; k < g.y.size(); ++k) {
    ASSERT_EQ(g.y[k], origin.y + static_cast<double>(g.first_j + static_cast<std::int64_t>(k)) * h);
  }
  EXPECT_LE(g.x.front(), lo.x);
  EXPECT_GE(g.x.back(), hi.x);
  EXPECT_LE(g.y.front(), lo.y);
  EXPECT_GE(g.y.back(), hi.y);
  const Rational a = widest_gap(g.x), b = widest_gap(g.y);
  const Rational reach(g.reach);
  ASSERT_GE(4 * reach * reach, a * a + b * b)
      << "origin (" << origin.x << ", " << origin.y << ") h " << h << " reach " << g.reach;
  // Not vacuous: about h / sqrt(2).
  EXPECT_LE(g.reach, h * 0.7072);
}

// Lines just past a power of two away from a small origin: the product i h and the sum both
// round, so a gap can exceed h by two ulps of the coordinate (the old allowance was the largest
// coordinate times 2^-52, which is short there). Then grids around real-looking boxes.
TEST(InkCertificateTerms, GridReachCoversTheWidestCell) {
  check_reach({-0.09692122429582735, -0.09692122429582735}, 0.06258449816539881,
              {-0.09692122429582735 + 8142 * 0.06258449816539881, 0.0},
              {-0.09692122429582735 + 8222 * 0.06258449816539881, 1.0});
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const double h = std::pow(10.0, -3.0 + 2.0 * u(rng));
    const double o = (u(rng) < 0.5 ? -1 : 1) * (0.3 + u(rng)) * h * (1 + trial % 5);
    const double at = std::ldexp(1.0, 3 + trial % 18); // lines around a power of two
    check_reach({o, o}, h, {at - 40 * h, at - 40 * h}, {at + 40 * h, at + 40 * h});
    const double big = (u(rng) - 0.5) * 2e6; // an ink box far from 0, origin at its corner
    check_reach({big, -big}, h, {big - 3 * h, -big - 3 * h}, {big + 300 * h, -big + 200 * h});
  }
}

// An arc starting at t0 = 2^40 rad (where doubles are 2^-12 apart) with a sweep whose end
// t0 + sweep lies just under half an ulp below the double it rounds to: the clean shape the
// certificate samples runs delta = (1/2 - 2^-10) 2^-12 rad past the true arc's end. The stroke
// (ink radius 1 around samples on the longer arc) is certified against the arc itself (pen radius
// 0, so the clean ink's side stays small and cannot hide the other): the ink's point one radius
// past its last sample along the tangent is at least 1 + R sin(delta) from the true arc, and the
// bound must not be below that (without the end term on the ink side it was about 1.17 < 1.48).
TEST(InkCertificateTerms, ArcEndRoundingIsAddedOnTheInkSide) {
  const double t0 = std::ldexp(1.0, 40), ulp = std::ldexp(1.0, -12);
  const double sweep = (40.5 + std::ldexp(1.0, -10)) * ulp;
  ASSERT_EQ(t0 + sweep, t0 + 41 * ulp); // rounds up past the true end
  const double radius = 4000.0, ink_radius = 1.0, delta = (0.5 - std::ldexp(1.0, -10)) * ulp;
  std::vector<InkSample> samples;
  for (int k = 0; k <= 41; ++k) {
    const double t = t0 + k * ulp; // exact
    samples.push_back({radius * std::cos(t), radius * std::sin(t), ink_radius});
  }
  InkOptions options;
  options.radius_mm = ink_radius;
  const InkPolygon ink = ink_polygon(samples, options);
  ShapeParams arc;
  arc.center = {0, 0};
  arc.radius_x = arc.radius_y = radius;
  arc.start_angle = t0;
  arc.sweep_angle = sweep;
  const Certificate cert = certify_ink(ink, ShapeClass::kArc, arc, 0.0, 0.5);
  // Every point of the true arc has angle <= t0 + sweep = last - delta: its projection on the
  // last sample's tangent is at most -R sin(delta), so the point an ink radius ahead is at least
  // R sin(delta) + 1 from it (less the samples' rounding, far below 1e-6).
  const double truth = ink_radius + radius * std::sin(delta) - 1e-6;
  EXPECT_GE(cert.bound, truth);
}

} // namespace
} // namespace penshape
