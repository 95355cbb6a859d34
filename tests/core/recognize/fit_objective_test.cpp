// The fitters' fast objective (FitObjective: scans that start at the last nearest segment and stop
// once a point cannot raise the maximum) against the plain definition computed here: the maximum
// of polyline_distance over every fit point and key point. They must agree bit for bit, for one
// objective reused over a search's many shapes (its hints carried from shape to shape), since
// the compass search compares these values and must take the same steps.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "recognize/fitting/fit.hpp"

namespace penshape::recognize_detail {
namespace {

// The objective's definition: every point against every segment.
double plain_objective(const PreparedStroke& s, const CleanShape& shape, bool key_points) {
  double worst = 0.0;
  for (const PointD& p : s.fit_points) worst = std::max(worst, shape.distance_to(p));
  if (shape.kind == CleanShape::Kind::kEllipse) worst = max_distance(s.fit_points, shape);
  if (!key_points) return worst;
  std::vector<PointD> keys = shape.path;
  if (shape.kind != CleanShape::Kind::kPolyline && !shape.full_curve()) {
    keys = {shape.at(shape.t0), shape.at(shape.t0 + shape.sweep)};
  }
  for (const PointD& v : keys) worst = std::max(worst, polyline_distance(v, s.points));
  return worst;
}

// A wobbly closed stroke around a rounded polygon of `corners` corners.
PreparedStroke wobbly_stroke(std::mt19937& rng, std::size_t corners) {
  std::uniform_real_distribution<double> wobble(-0.6, 0.6);
  std::vector<PointD> pts;
  const double r = 20.0;
  for (std::size_t i = 0; i <= 240; ++i) {
    const double a = 2 * std::numbers::pi * static_cast<double>(i) / 240.0;
    const double k = static_cast<double>(corners);
    const double bump = 1.0 + 0.15 * std::cos(k * a);
    pts.push_back(
        {50 + r * bump * std::cos(a) + wobble(rng), 40 + r * bump * std::sin(a) + wobble(rng)});
  }
  return prepare_points(pts, 0.05);
}

// The polygon of `corners` vertices a search might try: the stroke's corners moved a little.
CleanShape moved_polygon(std::mt19937& rng, std::size_t corners, double step) {
  std::uniform_real_distribution<double> move(-step, step);
  CleanShape c;
  for (std::size_t i = 0; i < corners; ++i) {
    const double a = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(corners);
    c.path.push_back({50 + 23 * std::cos(a) + move(rng), 40 + 23 * std::sin(a) + move(rng)});
  }
  c.path.push_back(c.path.front());
  return c;
}

TEST(RecognizeFitObjective, ReusedObjectiveEqualsTheDefinitionBitForBit) {
  std::mt19937 rng(26);
  for (std::size_t corners = 3; corners <= 8; ++corners) {
    const PreparedStroke s = wobbly_stroke(rng, corners);
    for (const bool keys : {true, false}) {
      FitObjective objective(s, keys);
      for (int trial = 0; trial < 200; ++trial) {
        // Small steps as a search takes, and now and then a jump far away.
        const CleanShape shape = moved_polygon(rng, corners, trial % 17 == 0 ? 15.0 : 1.0);
        const double fast = objective(shape);
        const double plain = plain_objective(s, shape, keys);
        ASSERT_EQ(fast, plain) << corners << " corners, trial " << trial;
        ASSERT_EQ(fit_objective(s, shape, keys), plain);
      }
    }
  }
}

// A search keeps a trial only when it beats its best: evaluated with that best as stop_at, the
// value is exact below it and at least stop_at otherwise, so the search takes the same steps
// (what the stop saves is timed by recognize_bench, not here).
TEST(RecognizeFitObjective, AStoppedEvaluationIsExactBelowTheStopAndAtLeastItOtherwise) {
  std::mt19937 rng(31);
  int not_better = 0, exact = 0;
  for (std::size_t corners = 3; corners <= 8; ++corners) {
    const PreparedStroke s = wobbly_stroke(rng, corners);
    for (const bool keys : {true, false}) {
      FitObjective objective(s, keys);
      double best = objective(moved_polygon(rng, corners, 1.0));
      for (int trial = 0; trial < 200; ++trial) {
        const CleanShape shape = moved_polygon(rng, corners, trial % 17 == 0 ? 15.0 : 1.0);
        const double plain = plain_objective(s, shape, keys);
        const double value = objective(shape, best);
        if (plain < best) {
          ASSERT_EQ(value, plain) << corners << " corners, trial " << trial;
          best = plain;
          ++exact;
        } else {
          ASSERT_GE(value, best) << corners << " corners, trial " << trial;
          ++not_better;
        }
      }
    }
  }
  EXPECT_GT(exact, 20); // both outcomes are exercised
  EXPECT_GT(not_better, 200);
}

TEST(RecognizeFitObjective, CurvesAndDegenerateShapesEqualTheDefinition) {
  std::mt19937 rng(7);
  const PreparedStroke s = wobbly_stroke(rng, 4);
  FitObjective objective(s, true);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 100; ++trial) {
    CleanShape arc;
    arc.kind = CleanShape::Kind::kCircle;
    arc.center = {50 + u(rng), 40 + u(rng)};
    arc.rx = arc.ry = 21 + u(rng);
    arc.t0 = u(rng);
    arc.sweep = 2.0 + u(rng);
    ASSERT_EQ(objective(arc), plain_objective(s, arc, true)) << trial;
    CleanShape point; // one vertex: distances to it
    point.path = {{50 + u(rng), 40 + u(rng)}};
    ASSERT_EQ(objective(point), plain_objective(s, point, true)) << trial;
    const CleanShape polygon = moved_polygon(rng, 4, 1.0);
    ASSERT_EQ(objective(polygon), plain_objective(s, polygon, true)) << trial;
  }
}

} // namespace
} // namespace penshape::recognize_detail
