// The recognizer's certified distances (core/src/recognize/certify/certified_distance.hpp) and the
// thinning's certified decision, against closed forms and dense sampling computed here: upper
// bounds are never below the true distance and stay close to it; a point exactly tau from its
// chord is dropped (the exact fallback decides), one ulp farther is kept.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "recognize/certify/certified_distance.hpp"
#include "recognize/fitting/thin_path.hpp"

namespace penshape::recognize_detail {
namespace {

constexpr double kPi = std::numbers::pi;

double seg_dist(PointD p, PointD a, PointD b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::max(0.0, std::min(1.0, t));
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

CleanShape circle(PointD c, double r, double t0 = 0, double sweep = 2 * kPi) {
  CleanShape s;
  s.kind = CleanShape::Kind::kCircle;
  s.center = c;
  s.rx = s.ry = r;
  s.t0 = t0;
  s.sweep = sweep;
  return s;
}

// min over a dense sampling of the curve (every curve point within `step` / 2 of a sample).
double dense_distance(PointD p, const CleanShape& s, std::size_t n, double& step) {
  double best = INFINITY;
  const double speed = std::max(s.rx, s.ry);
  step = std::abs(s.sweep) * speed / static_cast<double>(n);
  for (std::size_t k = 0; k <= n; ++k) {
    const double t = s.t0 + s.sweep * static_cast<double>(k) / static_cast<double>(n);
    const double c = std::cos(s.rotation), sn = std::sin(s.rotation);
    const double ex = s.rx * std::cos(t), ey = s.ry * std::sin(t);
    best = std::min(best, std::hypot(p.x - (s.center.x + c * ex - sn * ey),
                                     p.y - (s.center.y + sn * ex + c * ey)));
  }
  return best;
}

TEST(CertifiedDistance, UpperBoundsOnCurvesAreSoundAndTight) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-150, 150);
  CleanShape ellipse;
  ellipse.kind = CleanShape::Kind::kEllipse;
  ellipse.center = {10, -20};
  ellipse.rx = 80;
  ellipse.ry = 30;
  ellipse.rotation = 0.6;
  const CleanShape shapes[] = {circle({3, 4}, 50), circle({0, 0}, 60, 0.3, 2.0),
                               circle({0, 0}, 60, 1.0, -4.0), ellipse};
  for (const CleanShape& s : shapes) {
    const CertifiedShape cs(s);
    for (int i = 0; i < 300; ++i) {
      const PointD p{u(rng), u(rng)};
      double step = 0;
      const double dense = dense_distance(p, s, 100'000, step);
      const double up = cs.upper(detail::enclose(p), p);
      EXPECT_GE(up, dense - step / 2 - 1e-9) << p.x << " " << p.y;
      if (s.kind == CleanShape::Kind::kEllipse) {
        // The foot point is proposed by Newton's method (as ellipse_distance), which can stop at
        // a poor foot for points inside near the major axis: the bound is then loose, never
        // wrong. It is the proposal's own distance, enclosed.
        EXPECT_LE(up, ellipse_distance(p, s) + 1e-9) << p.x << " " << p.y;
      } else {
        EXPECT_LE(up, dense + 1e-6) << p.x << " " << p.y;
      }
    }
  }
}

TEST(CertifiedDistance, PolylineAndSideBounds) {
  CleanShape z;
  z.path = {{0, 0}, {100, 0}, {0, 60}, {100, 60}};
  const CertifiedShape cs(z);
  // A stroke segment crossing the Z: its farthest point from the Z by dense sampling.
  const PointD a{-20, 30}, b{120, 35};
  double worst = 0;
  for (int k = 0; k <= 100'000; ++k) {
    const double f = k / 100'000.0;
    const PointD p{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
    double d = INFINITY;
    for (std::size_t i = 0; i + 1 < z.path.size(); ++i)
      d = std::min(d, seg_dist(p, z.path[i], z.path[i + 1]));
    worst = std::max(worst, d);
  }
  const double h = 0.5;
  const double bound = segment_to_shape(a, b, h, cs);
  EXPECT_GE(bound, worst);
  EXPECT_LE(bound, worst + h);
  // The Z against that one segment: farthest is the Z's corner (0, 0) or (100, 60)... densely.
  const SegmentIndex index({{a, b}}, 10.0);
  double far = 0;
  for (std::size_t i = 0; i + 1 < z.path.size(); ++i) {
    for (int k = 0; k <= 10'000; ++k) {
      const double f = k / 10'000.0;
      const PointD p{z.path[i].x + f * (z.path[i + 1].x - z.path[i].x),
                     z.path[i].y + f * (z.path[i + 1].y - z.path[i].y)};
      far = std::max(far, seg_dist(p, a, b));
    }
  }
  const double shape_side = cs.farthest_from(index, h);
  EXPECT_GE(shape_side, far);
  EXPECT_LE(shape_side, far + h);
}

TEST(CertifiedDistance, CircleSideCoversTheWholeCircle) {
  // The stroke is a chord polygon of the circle: the circle's farthest points from it are the
  // arcs' midpoints, at the sagitta r (1 - cos(pi / n)).
  const double r = 40;
  const int n = 12;
  std::vector<Segment> polygon;
  for (int k = 0; k < n; ++k) {
    const double t0 = 2 * kPi * k / n, t1 = 2 * kPi * (k + 1) / n;
    polygon.push_back({{r * std::cos(t0), r * std::sin(t0)}, {r * std::cos(t1), r * std::sin(t1)}});
  }
  const double sagitta = r * (1 - std::cos(kPi / n));
  const CleanShape shape = circle({0, 0}, r); // CertifiedShape keeps a reference
  const CertifiedShape cs(shape);
  const double h = 0.05;
  const double bound = cs.farthest_from(SegmentIndex(polygon, 5.0), h);
  EXPECT_GE(bound, sagitta);
  EXPECT_LE(bound, sagitta + h);
}

// "Closed" is decided exactly (issue #22: a hand-chosen 1e-12 took arcs up to 1e-12 rad short of
// a turn for the whole circle). The double nearest 2 pi is a full curve (its missing sliver is
// covered by end_slack), anything below it an arc; and a point in the gap of an arc that misses
// 5e-13 rad of a circle of radius 10^6 is about 2.5e-7 from it, which the bound must see.
TEST(CertifiedDistance, NearlyFullArcIsAnArc) {
  const double d = 2 * kPi;
  EXPECT_TRUE(circle({0, 0}, 1).full_curve());
  EXPECT_TRUE(circle({0, 0}, 1, 0, -d).full_curve());
  EXPECT_TRUE(circle({0, 0}, 1, 0, std::nextafter(d, 7.0)).full_curve());
  EXPECT_FALSE(circle({0, 0}, 1, 0, std::nextafter(d, 0.0)).full_curve());
  EXPECT_FALSE(circle({0, 0}, 1, 0, d - 1e-13).full_curve());
  const double radius = 1e6, gap = 5e-13;
  const CleanShape arc = circle({0, 0}, radius, 0, d - gap);
  const CertifiedShape certified(arc);
  const PointD p{radius * std::cos(gap / 2), -radius * std::sin(gap / 2)}; // mid-gap
  // The arc's points have angles in [0, 2 pi - gap]: the nearest is an end, at least the chord
  // of half the gap (minus the rounding of p, far below 1e-9).
  const double truth = 2 * radius * std::sin(gap / 4) - 1e-9;
  EXPECT_GE(certified.upper(detail::enclose(p), p) + certified.end_slack(), truth);
}

TEST(CertifiedThinning, ExactlyTauIsWithinOneUlpFartherIsNot) {
  // d((5, 0.1), chord (0,0)-(10,0)) is exactly the double 0.1 = tau: intervals cannot tell,
  // rationals decide "within".
  const std::vector<PointD> at{{0, 0}, {5, 0.1}, {10, 0}};
  EXPECT_EQ(thin_path(at, 0.1).size(), 2U);
  const std::vector<PointD> beyond{{0, 0}, {5, std::nextafter(0.1, 1.0)}, {10, 0}};
  EXPECT_EQ(thin_path(beyond, 0.1).size(), 3U);
  // A long wobbly path: every dropped point within tau of the chord of the kept ones around it.
  std::vector<PointD> path;
  path.reserve(2000);
  for (int k = 0; k < 2000; ++k) path.push_back({k * 0.37, std::sin(k * 0.05) * 3});
  const double tau = 0.2;
  const std::vector<PointD> kept = thin_path(path, tau);
  std::size_t j = 0;
  for (const PointD& p : path) {
    while (j + 1 < kept.size() && !(kept[j + 1].x > p.x)) ++j;
    if (j + 1 < kept.size()) {
      EXPECT_LE(seg_dist(p, kept[j], kept[j + 1]), tau + 1e-12);
    }
  }
  EXPECT_LT(kept.size(), path.size() / 4);
}

} // namespace
} // namespace penshape::recognize_detail
