// The greedy P^s: at most OPT + 1 vertices on offsets of shapes with a known optimum, and an
// independently checked certificate.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "penshape/core/convex_deconstruct.hpp"

namespace penshape {
namespace {

using Poly = std::vector<PointD>;

Poly convex_hull(Poly pts) {
  std::sort(pts.begin(), pts.end(),
            [](PointD a, PointD b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  auto cross = [](PointD o, PointD a, PointD b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  Poly h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i - 1]) <= 0) --k;
    h[k++] = pts[i - 1];
  }
  h.resize(k - 1);
  return h;
}

// The r-offset of a convex polygon (or segment), with the disk as a 96-gon circumscribing
// nothing in particular (vertices on the circle): the ink of a pen tracing the shape.
Poly offset_of(const Poly& shape, double r, std::mt19937* jitter_rng, double jitter) {
  Poly pts;
  for (const auto& v : shape) {
    for (int k = 0; k < 96; ++k) {
      const double a = 2 * std::numbers::pi * k / 96;
      double rr = r;
      if (jitter_rng != nullptr)
        rr += std::uniform_real_distribution<double>(-jitter, jitter)(*jitter_rng);
      pts.push_back({v.x + rr * std::cos(a), v.y + rr * std::sin(a)});
    }
  }
  return convex_hull(pts);
}

PolygonSet polygon(const Poly& pts) {
  PolygonSet q;
  q.polygons.emplace_back();
  for (const auto& p : pts) q.polygons[0].outer.push_back(exact(p));
  return q;
}

double segment_distance(PointD p, PointD s, PointD t) {
  const double dx = t.x - s.x;
  const double dy = t.y - s.y;
  const double len2 = dx * dx + dy * dy;
  double u = len2 > 0 ? ((p.x - s.x) * dx + (p.y - s.y) * dy) / len2 : 0.0;
  u = std::clamp(u, 0.0, 1.0);
  return std::hypot(p.x - (s.x + u * dx), p.y - (s.y + u * dy));
}

// Independent check of the certificate: every vertex of Q within r + ε of P (doubles), and P
// at least r - ε inside every edge line of Q.
void expect_certified(const Poly& q, const PolygonSet& p_set, double r, double eps) {
  ASSERT_EQ(p_set.polygons.size(), 1U);
  Poly p;
  for (const auto& v : p_set.polygons[0].outer) p.push_back(to_double(v));
  for (const auto& v : q) {
    double best = INFINITY;
    if (p.size() == 1) best = std::hypot(v.x - p[0].x, v.y - p[0].y);
    for (std::size_t j = 0; p.size() > 1 && j < p.size(); ++j) {
      best = std::min(best, segment_distance(v, p[j], p[(j + 1) % p.size()]));
    }
    EXPECT_LE(best, (r + eps) * (1 + 1e-9));
  }
  for (const auto& v : p) {
    for (std::size_t i = 0; i < q.size(); ++i) {
      const PointD s = q[i];
      const PointD t = q[(i + 1) % q.size()];
      const double a = t.y - s.y;
      const double b = s.x - t.x;
      EXPECT_GE((a * s.x + b * s.y - a * v.x - b * v.y) / std::hypot(a, b), (r - eps) * (1 - 1e-9));
    }
  }
}

std::size_t greedy_vertices(const Poly& q_pts, double r, double eps) {
  const PolygonSet q = polygon(q_pts);
  const DeconstructParams params{exact(r), exact(eps), exact(eps / 8), EngineKind::kFast};
  const DeconstructResult yes = convex_decide(q, params);
  EXPECT_EQ(yes.answer, Answer::kYes);
  if (yes.answer != Answer::kYes) return 0;
  const GreedyResult g = convex_greedy_solution(q, yes.solution, params.radius + params.tolerance);
  EXPECT_FALSE(g.fell_back);
  expect_certified(q_pts, g.solution, r, eps);
  return g.vertices;
}

Poly regular(int n, double radius, double phase) {
  Poly out;
  for (int k = 0; k < n; ++k) {
    const double a = phase + 2 * std::numbers::pi * k / n;
    out.push_back({radius * std::cos(a), radius * std::sin(a)});
  }
  return out;
}

TEST(ConvexGreedy, OffsetsOfPolygonsNeedAtMostOptPlusOne) {
  std::mt19937 rng(3);
  for (const int n : {3, 4, 5, 6, 8}) {
    for (int trial = 0; trial < 4; ++trial) {
      const double r = 3.0;
      const double eps = 0.6;
      const Poly shape = regular(n, 40, 0.3 * trial);
      const Poly q = offset_of(shape, r, &rng, eps / 10); // jitter below ε
      const std::size_t v = greedy_vertices(q, r, eps);
      EXPECT_GE(v, 2U);
      EXPECT_LE(v, static_cast<std::size_t>(n) + 1) << "n = " << n << " trial " << trial;
    }
  }
}

TEST(ConvexGreedy, StraightWideStrokeIsASegment) {
  const Poly q = offset_of({{0, 0}, {100, 20}}, 4.0, nullptr, 0);
  EXPECT_EQ(greedy_vertices(q, 4.0, 1.0), 2U);
}

TEST(ConvexGreedy, DotIsAPointOrTinySegment) {
  const Poly q = offset_of({{5, 5}}, 4.0, nullptr, 0);
  EXPECT_LE(greedy_vertices(q, 4.0, 1.0), 2U);
}

TEST(ConvexGreedy, RandomConvexInputsStayCertified) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 40; ++trial) {
    Poly pts;
    std::uniform_real_distribution<double> u(-50, 50);
    for (int i = 0; i < 30; ++i) pts.push_back({u(rng), u(rng)});
    const Poly q = convex_hull(pts);
    const double r = std::uniform_real_distribution<double>(1, 6)(rng);
    const double eps = r * 0.5;
    const PolygonSet qs = polygon(q);
    const DeconstructParams params{exact(r), exact(eps), exact(eps / 8), EngineKind::kFast};
    const DeconstructResult res = convex_decide(qs, params);
    if (res.answer != Answer::kYes) continue;
    const GreedyResult g =
        convex_greedy_solution(qs, res.solution, params.radius + params.tolerance);
    EXPECT_FALSE(g.fell_back) << trial;
    EXPECT_LE(g.vertices, res.solution.polygons[0].outer.size());
    expect_certified(q, g.solution, r, eps);
  }
}

} // namespace
} // namespace penshape
