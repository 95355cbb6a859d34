// The recognizer on synthetic strokes with known answers: clean and noisy shapes, scribbles and
// handwriting-like strokes, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "penshape/core/point_arithmetic.hpp"
#include "penshape/core/recognize.hpp"
#include "test_support.hpp"

namespace penshape {
namespace {

using Points = std::vector<StrokePoint>;

// Samples along a polyline every `step` units, with Gaussian jitter of `noise`.
Points along(const std::vector<PointD>& corners, double step, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> jitter(0.0, noise);
  Points out;
  double t = 0;
  for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
    const PointD a = corners[i], b = corners[i + 1];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const int n = std::max(1, static_cast<int>(len / step));
    for (int k = 0; k < n; ++k) {
      const double f = static_cast<double>(k) / n;
      out.push_back({a.x + f * (b.x - a.x) + (noise > 0 ? jitter(rng) : 0),
                     a.y + f * (b.y - a.y) + (noise > 0 ? jitter(rng) : 0), t});
      t += 0.01;
    }
  }
  out.push_back({corners.back().x, corners.back().y, t});
  return out;
}

Points ellipse(double cx, double cy, double a, double b, double rot, double turns, double noise,
               unsigned seed) {
  std::vector<PointD> pts;
  const int n = static_cast<int>(120 * turns);
  for (int k = 0; k <= n; ++k) {
    const double t = 2 * std::numbers::pi * turns * k / n;
    const double x = a * std::cos(t), y = b * std::sin(t);
    pts.push_back(
        {cx + std::cos(rot) * x - std::sin(rot) * y, cy + std::sin(rot) * x + std::cos(rot) * y});
  }
  return along(pts, 1.0, noise, seed);
}

Points regular(double cx, double cy, double r, int n, double rot, double noise, unsigned seed) {
  std::vector<PointD> c;
  for (int k = 0; k <= n; ++k) {
    const double a = rot + 2 * std::numbers::pi * k / n;
    c.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return along(c, 2.0, noise, seed);
}

struct Case {
  const char* name;
  Points points;
  ShapeClass expected;
};

std::vector<Case> clean_cases(double noise, unsigned seed) {
  return {
      {"segment", along({{0, 0}, {200, 60}}, 2, noise, seed), ShapeClass::kSegment},
      {"V polyline", along({{0, 0}, {80, 160}, {160, 0}}, 2, noise, seed), ShapeClass::kPolyline},
      {"bracket polyline", along({{100, 0}, {0, 0}, {0, 200}, {100, 200}}, 2, noise, seed),
       ShapeClass::kPolyline},
      {"triangle", along({{0, 0}, {200, 10}, {90, 170}, {0, 0}}, 2, noise, seed),
       ShapeClass::kTriangle},
      {"rectangle", along({{0, 0}, {240, 0}, {240, 120}, {0, 120}, {0, 0}}, 2, noise, seed),
       ShapeClass::kRectangle},
      {"tilted rectangle",
       along({{0, 0}, {207.8, 120}, {147.8, 223.9}, {-60, 103.9}, {0, 0}}, 2, noise, seed),
       ShapeClass::kRectangle},
      {"square", along({{0, 0}, {150, 0}, {150, 150}, {0, 150}, {0, 0}}, 2, noise, seed),
       ShapeClass::kSquare},
      {"diamond", along({{100, 0}, {200, 150}, {100, 300}, {0, 150}, {100, 0}}, 2, noise, seed),
       ShapeClass::kDiamond},
      // A rhombus of 60 and 120 degrees, its long diagonal turned 30 degrees.
      {"tilted diamond",
       along({{130, 75}, {-43.3, 75}, {-130, -75}, {43.3, -75}, {130, 75}}, 2, noise, seed),
       ShapeClass::kDiamond},
      {"square on a corner",
       along({{100, 0}, {200, 100}, {100, 200}, {0, 100}, {100, 0}}, 2, noise, seed),
       ShapeClass::kSquare},
      {"quadrilateral", along({{0, 0}, {220, 30}, {160, 160}, {30, 200}, {0, 0}}, 2, noise, seed),
       ShapeClass::kQuadrilateral},
      {"pentagon", regular(100, 100, 100, 5, 0.3, noise, seed), ShapeClass::kRegularPolygon},
      {"house pentagon",
       along({{0, 80}, {100, 0}, {200, 80}, {200, 200}, {0, 200}, {0, 80}}, 2, noise, seed),
       ShapeClass::kPolygon},
      {"L hexagon",
       along({{0, 0}, {200, 0}, {200, 80}, {80, 80}, {80, 200}, {0, 200}, {0, 0}}, 2, noise, seed),
       ShapeClass::kPolygon},
      {"circle", ellipse(100, 100, 80, 80, 0, 1.0, noise, seed), ShapeClass::kCircle},
      {"ellipse", ellipse(100, 100, 120, 50, 0.5, 1.0, noise, seed), ShapeClass::kEllipse},
      {"arc", ellipse(100, 100, 90, 90, 0, 0.45, noise, seed), ShapeClass::kArc},
  };
}

void expect_certified_snap(const Case& c, const Recognition& r) {
  ASSERT_TRUE(r.certificate.certified) << c.name;
  const test::IndependentCheck check = test::independent_hausdorff(c.points, r, r.epsilon / 20);
  EXPECT_LE(check.hausdorff - check.slack, r.certificate.bound * (1 + 1e-9)) << c.name;
  EXPECT_LE(r.certificate.bound, r.epsilon) << c.name;
}

TEST(RecognizeSynthetic, CleanShapesSnapToTheirClass) {
  for (const Case& c : clean_cases(0.0, 1)) {
    const Recognition r = recognize(c.points);
    EXPECT_EQ(to_string(r.shape), std::string(to_string(c.expected))) << c.name;
    if (r.shape != ShapeClass::kFreeform) expect_certified_snap(c, r);
  }
}

TEST(RecognizeSynthetic, NoisyShapesSnapToTheirClass) {
  // Jitter of 1.5 units on drawings 150..300 units across, three seeds each.
  for (unsigned seed = 1; seed <= 3; ++seed) {
    for (const Case& c : clean_cases(1.5, seed)) {
      const Recognition r = recognize(c.points);
      std::string why;
      for (const Candidate& a : r.alternatives) {
        why += std::string(" ") + to_string(a.shape) + ":" + std::to_string(a.certificate.bound) +
               (a.rejected.empty() ? "" : "(" + a.rejected + ")");
      }
      EXPECT_EQ(to_string(r.shape), std::string(to_string(c.expected)))
          << c.name << " seed " << seed << " epsilon " << r.epsilon << why;
      if (r.shape != ShapeClass::kFreeform) expect_certified_snap(c, r);
    }
  }
}

// A rhombus with half-diagonals a (along theta) and b, centred at c, drawn from its first corner.
Points rhombus(PointD c, double a, double b, double theta) {
  const PointD u{std::cos(theta), std::sin(theta)}, v{-u.y, u.x};
  const PointD p0 = c + a * u, p1 = c + b * v, p2 = c - a * u, p3 = c - b * v;
  return along({p0, p1, p2, p3, p0}, 2, 0, 1);
}

TEST(RecognizeDiamond, ParametersAreTheRhombus) {
  // 60 and 120 degree corners (b = a tan 30), long diagonal at 30 degrees.
  const double theta = std::numbers::pi / 6;
  const Recognition r = recognize(rhombus({50, 40}, 150, 150 * std::tan(theta), theta));
  ASSERT_EQ(r.shape, ShapeClass::kDiamond);
  EXPECT_NEAR(r.params.center.x, 50, 1.5);
  EXPECT_NEAR(r.params.center.y, 40, 1.5);
  EXPECT_NEAR(r.params.rotation, theta, 0.02);
  EXPECT_NEAR(r.params.radius_x, 150, 2.0);
  EXPECT_NEAR(r.params.radius_y, 150 * std::tan(theta), 2.0);
  ASSERT_EQ(r.params.vertices.size(), 4U);
}

TEST(RecognizeDiamond, NearSquareRhombusIsNoDiamond) {
  // Angles 82 and 98 degrees (within 15 degrees of right ones): a square drawn skewed.
  const double half = 41.0 * std::numbers::pi / 180;
  const Recognition r = recognize(rhombus({0, 0}, 120, 120 * std::tan(half), 0.2));
  EXPECT_NE(r.shape, ShapeClass::kDiamond);
  EXPECT_NE(r.shape, ShapeClass::kFreeform);
  bool tried = false;
  for (const Candidate& a : r.alternatives) {
    if (a.shape == ShapeClass::kDiamond && a.certificate.certified) {
      tried = true;
      EXPECT_NE(a.rejected.find("right angles"), std::string::npos) << a.rejected;
    }
  }
  EXPECT_TRUE(tried);
}

TEST(RecognizeSynthetic, ParametersOfCleanShapes) {
  const Recognition circle = recognize(ellipse(100, 50, 80, 80, 0, 1.0, 0, 1));
  ASSERT_EQ(circle.shape, ShapeClass::kCircle);
  EXPECT_NEAR(circle.params.center.x, 100, 1.0);
  EXPECT_NEAR(circle.params.center.y, 50, 1.0);
  EXPECT_NEAR(circle.params.radius_x, 80, 1.0);
  const Recognition seg = recognize(along({{0, 0}, {200, 60}}, 2, 0, 1));
  ASSERT_EQ(seg.shape, ShapeClass::kSegment);
  ASSERT_EQ(seg.params.vertices.size(), 2U);
  EXPECT_NEAR(seg.params.vertices[0].x, 0, 1.0);
  EXPECT_NEAR(seg.params.vertices[1].y, 60, 1.0);
  const Recognition rect =
      recognize(along({{0, 0}, {240, 0}, {240, 120}, {0, 120}, {0, 0}}, 2, 0, 1));
  ASSERT_EQ(rect.shape, ShapeClass::kRectangle);
  EXPECT_NEAR(rect.params.center.x, 120, 1.0);
  EXPECT_NEAR(rect.params.center.y, 60, 1.0);
  EXPECT_NEAR(2 * rect.params.radius_x, 240, 2.0);
  EXPECT_NEAR(2 * rect.params.radius_y, 120, 2.0);
  EXPECT_GT(rect.confidence, 0.9);
  EXPECT_FALSE(rect.alternatives.empty());
}

TEST(RecognizeSynthetic, ScribblesDoNotSnap) {
  std::mt19937 rng(7);
  std::normal_distribution<double> step(0.0, 12.0);
  int snaps = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Points p;
    double x = 0, y = 0, vx = 0, vy = 0;
    for (int k = 0; k < 150; ++k) {
      vx = 0.7 * vx + step(rng);
      vy = 0.7 * vy + step(rng);
      x += vx;
      y += vy;
      p.push_back({x, y, k * 0.01});
    }
    if (recognize(p).shape != ShapeClass::kFreeform) ++snaps;
  }
  EXPECT_LE(snaps, 1) << "random scribbles must stay ink";
}

TEST(RecognizeSynthetic, AStarIsNoPolygon) {
  // A five-pointed star drawn in one stroke visits its points in star order: the closed path of
  // its five corners crosses itself, so no polygon (a polygon does not cross itself).
  std::vector<PointD> c;
  for (int k = 0; k <= 5; ++k) {
    const double a = -std::numbers::pi / 2 + 4 * std::numbers::pi * k / 5;
    c.push_back({100 + 100 * std::cos(a), 100 + 100 * std::sin(a)});
  }
  const Recognition r = recognize(along(c, 2, 0.0, 1));
  EXPECT_NE(r.shape, ShapeClass::kPolygon);
  bool refused = false;
  for (const Candidate& a : r.alternatives) {
    refused = refused || (a.shape == ShapeClass::kPolygon && a.params.vertices.size() == 5 &&
                          a.rejected.find("crosses itself") != std::string::npos);
  }
  EXPECT_TRUE(refused) << "the five-corner polygon is refused for crossing itself";
}

TEST(RecognizeSynthetic, HandwritingDoesNotSnap) {
  // Cursive-like loops ("eeee", "mmm", "www") sweeping right.
  int snaps = 0;
  for (int kind = 0; kind < 3; ++kind) {
    for (int letters = 2; letters <= 6; ++letters) {
      Points p;
      const int n = 60 * letters;
      for (int k = 0; k <= n; ++k) {
        const double t = 2 * std::numbers::pi * letters * k / n;
        double x = 0, y = 0;
        if (kind == 0) {
          x = 12 * t + 20 * std::cos(t);
          y = 25 * std::sin(t);
        } else if (kind == 1) {
          x = 12 * t;
          y = -30 * std::abs(std::sin(t / 2));
        } else {
          x = 12 * t;
          y = 30 * std::abs(std::cos(t)) + 3 * std::sin(5 * t);
        }
        p.push_back({x, y, k * 0.01});
      }
      if (recognize(p).shape != ShapeClass::kFreeform) ++snaps;
    }
  }
  EXPECT_EQ(snaps, 0);
}

TEST(RecognizeSynthetic, TighterToleranceRejectsTheSameStroke) {
  const Points p = ellipse(0, 0, 100, 100, 0, 1.0, 3.0, 5);
  RecognizerConfig loose;
  EXPECT_EQ(recognize(p, loose).shape, ShapeClass::kCircle);
  RecognizerConfig tight;
  tight.tolerance = 2.0; // below the jitter's extremes (3 units sigma)
  EXPECT_EQ(recognize(p, tight).shape, ShapeClass::kFreeform);
}

TEST(RecognizeSynthetic, DefaultTolerance) {
  const Points p = along({{0, 0}, {300, 0}, {300, 400}}, 2, 0, 1); // diagonal 500
  RecognizerConfig c;
  const ToleranceChoice t = choose_tolerance(p, c);
  EXPECT_DOUBLE_EQ(t.size, 500);
  EXPECT_DOUBLE_EQ(t.pen_radius, c.default_pen_radius_fraction * 500);
  EXPECT_DOUBLE_EQ(t.epsilon,
                   std::min(c.tolerance_size_fraction * 500 + c.tolerance_pen_radii * t.pen_radius,
                            c.max_tolerance_fraction * 500));
  c.pen_radius = 2;
  EXPECT_DOUBLE_EQ(choose_tolerance(p, c).epsilon,
                   std::min(c.tolerance_size_fraction * 500 + c.tolerance_pen_radii * 2,
                            c.max_tolerance_fraction * 500));
  c.pen_radius = 100; // a huge pen: bounded by the drawing size
  EXPECT_DOUBLE_EQ(choose_tolerance(p, c).epsilon, c.max_tolerance_fraction * 500);
}

TEST(RecognizeBadInput, RejectedWithAClearError) {
  auto message = [](const Points& p) {
    try {
      (void)recognize(p);
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({}).find("no samples"), std::string::npos);
  EXPECT_EQ(message({{1, 2, 0}, {1, 2, 1}}), "no error"); // a dot (dot_test.cpp)
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(message({{0, 0, 0}, {nan, 1, 1}}).find("sample 1 is not finite"), std::string::npos);
  EXPECT_NE(message({{0, 0, 0}, {1, INFINITY, 1}}).find("not finite"), std::string::npos);
  EXPECT_NE(message({{0, 0, 0}, {1e300, 1, 1}}).find("limit"), std::string::npos);
  RecognizerConfig small;
  small.max_samples = 3;
  EXPECT_THROW((void)recognize({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}, small), InvalidInput);
}

TEST(RecognizeBadInput, TwoPointsAreASegment) {
  const Recognition r = recognize({{0, 0, 0}, {100, 0, 1}});
  EXPECT_EQ(r.shape, ShapeClass::kSegment);
  EXPECT_TRUE(r.certificate.certified);
}

} // namespace
} // namespace penshape

namespace penshape {
namespace {

TEST(RecognizeBadInput, BadConfiguration) {
  const std::vector<StrokePoint> p{{0, 0, 0}, {100, 0, 1}};
  RecognizerConfig c;
  c.tolerance = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)recognize(p, c), InvalidInput);
  c = {};
  c.pen_radius = -1;
  EXPECT_THROW((void)recognize(p, c), InvalidInput);
  c = {};
  c.max_tolerance_fraction = 0;
  EXPECT_THROW((void)recognize(p, c), InvalidInput);
}

} // namespace
} // namespace penshape

namespace penshape {
namespace {

TEST(RecognizeBadInput, DegenerateStrokesGiveAnswersNotCrashes) {
  // Back and forth along one line (closed, but with no area): no closed shape can hold.
  std::vector<StrokePoint> back_and_forth;
  for (int k = 0; k <= 100; ++k) back_and_forth.push_back({k * 1.0, 0, k * 0.01});
  for (int k = 100; k >= 0; --k) back_and_forth.push_back({k * 1.0, 0, 2 - k * 0.01});
  const Recognition r = recognize(back_and_forth);
  EXPECT_TRUE(r.shape == ShapeClass::kFreeform || r.shape == ShapeClass::kSegment)
      << to_string(r.shape);
  // Far from the origin, tiny: the rounding margin follows the coordinates.
  std::vector<StrokePoint> far;
  for (int k = 0; k <= 50; ++k) far.push_back({9e8 + k * 0.01, -9e8 + k * 0.02, k * 0.01});
  const Recognition f = recognize(far);
  EXPECT_EQ(f.shape, ShapeClass::kSegment);
  EXPECT_TRUE(f.certificate.certified);
  // Repeated samples between distinct ones.
  const Recognition d = recognize({{0, 0, 0}, {0, 0, 1}, {50, 0, 2}, {50, 0, 3}, {100, 0, 4}});
  EXPECT_EQ(d.shape, ShapeClass::kSegment);
}

} // namespace
} // namespace penshape
