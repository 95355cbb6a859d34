// The kernel's Douglas–Peucker (geometry/douglas_peucker.hpp) against the definition: on random
// chains and rings, every dropped point lies within the tolerance of the chord of the kept points
// around it, the kept set is what a plain recursive Douglas–Peucker written here keeps, the
// caller's chord test is what drops points, and a measure that compares nothing (NaN) keeps
// points rather than looping.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "geometry/distance_kernel.hpp"
#include "geometry/douglas_peucker.hpp"

namespace penshape::detail {
namespace {

std::vector<PointD> random_walk(std::mt19937_64& rng, std::size_t n) {
  std::normal_distribution<double> step(0.0, 1.0);
  std::vector<PointD> path{{0, 0}};
  while (path.size() < n) path.push_back({path.back().x + step(rng), path.back().y + step(rng)});
  return path;
}

// Recursive Douglas–Peucker as textbooks write it (first farthest point, strict threshold).
void reference(const std::vector<PointD>& p, std::size_t a, std::size_t b, double tol,
               std::vector<char>& keep) {
  double worst = -1;
  std::size_t at = a;
  for (std::size_t k = a + 1; k < b; ++k) {
    const double d = proposed_distance(p[k], p[a], p[b]);
    if (d > worst) {
      worst = d;
      at = k;
    }
  }
  if (at == a || worst <= tol) return;
  keep[at] = 1;
  reference(p, a, at, tol, keep);
  reference(p, at, b, tol, keep);
}

TEST(DouglasPeucker, OpenChainsMatchTheDefinition) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    const auto path = random_walk(rng, 2 + static_cast<std::size_t>(trial));
    const double tol = 0.5 + 0.02 * trial;
    const std::size_t last = path.size() - 1;
    std::vector<char> keep(path.size(), 0), expected(path.size(), 0);
    keep[0] = keep[last] = expected[0] = expected[last] = 1;
    douglas_peucker(
        0, last,
        [&](std::size_t k, std::size_t i, std::size_t j) {
          return proposed_distance(path[k], path[i], path[j]);
        },
        [&](std::size_t, std::size_t, double worst) { return worst <= tol; }, keep);
    reference(path, 0, last, tol, expected);
    ASSERT_EQ(keep, expected) << trial;
    // Every dropped point within tol of the chord of its kept neighbours.
    std::size_t prev = 0;
    for (std::size_t k = 1; k <= last; ++k) {
      if (!keep[k]) continue;
      for (std::size_t m = prev + 1; m < k; ++m) {
        ASSERT_LE(proposed_distance(path[m], path[prev], path[k]), tol) << trial;
      }
      prev = k;
    }
  }
}

// The caller's chord test decides alone: one that refuses every chord keeps every point, one that
// accepts every chord keeps only the ends.
TEST(DouglasPeucker, TheChordTestDecides) {
  std::mt19937_64 rng(6);
  const auto path = random_walk(rng, 50);
  const auto measure = [&](std::size_t k, std::size_t i, std::size_t j) {
    return proposed_squared_distance(path[k], path[i], path[j]);
  };
  std::vector<char> all(path.size(), 0), ends(path.size(), 0);
  douglas_peucker(
      0, path.size() - 1, measure, [](std::size_t, std::size_t, double) { return false; }, all);
  douglas_peucker(
      0, path.size() - 1, measure, [](std::size_t, std::size_t, double) { return true; }, ends);
  for (std::size_t k = 1; k + 1 < path.size(); ++k) {
    EXPECT_EQ(all[k], 1) << k;
    EXPECT_EQ(ends[k], 0) << k;
  }
}

// Of two points equally far from the chord the first is kept (the callers' strict comparison):
// (1, 1) and (3, 1) are both 1 from the chord (0, 0)-(4, 0), and the kept one decides the rest.
TEST(DouglasPeucker, TiesKeepTheFirstFarthestPoint) {
  const std::vector<PointD> path{{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}};
  std::vector<char> keep(path.size(), 0), expected(path.size(), 0);
  keep[0] = keep[4] = expected[0] = expected[4] = 1;
  douglas_peucker(
      0, 4,
      [&](std::size_t k, std::size_t i, std::size_t j) {
        return proposed_distance(path[k], path[i], path[j]);
      },
      [](std::size_t, std::size_t, double worst) { return worst <= 0.7; }, keep);
  reference(path, 0, 4, 0.7, expected);
  EXPECT_EQ(keep, (std::vector<char>{1, 1, 0, 0, 1}));
  EXPECT_EQ(keep, expected);
}

TEST(DouglasPeucker, NanMeasuresKeepPointsAndTerminate) {
  std::vector<char> keep(6, 0);
  douglas_peucker(
      0, 5, [](std::size_t, std::size_t, std::size_t) { return std::nan(""); },
      [](std::size_t, std::size_t, double) { return false; }, keep);
  EXPECT_EQ(keep, (std::vector<char>{0, 1, 1, 1, 1, 0}));
}

// A ring: vertex 0 and the farthest vertex kept, the chain past `far` wraps to vertex 0.
TEST(DouglasPeucker, RingsSplitAtTheFarthestVertex) {
  // A square with points along its sides: only the corners survive.
  const std::vector<PointD> ring{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  const std::size_t n = ring.size();
  const std::size_t far = farthest_from_first(
      n, [&](std::size_t k) { return std::hypot(ring[k].x - ring[0].x, ring[k].y - ring[0].y); });
  EXPECT_EQ(far, 4U);
  const std::vector<char> keep = douglas_peucker_ring(
      n, far,
      [&](std::size_t k, std::size_t i, std::size_t j) {
        return proposed_distance(ring[k % n], ring[i % n], ring[j % n]);
      },
      [](std::size_t, std::size_t, double worst) { return worst <= 0.1; });
  EXPECT_EQ(keep, (std::vector<char>{1, 0, 1, 0, 1, 0, 1, 0}));
}

} // namespace
} // namespace penshape::detail
