// SVG geometry parsing (clients/snap/path_data.hpp, transform.hpp) against hand-computed values
// and the curves' own equations.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "snap/path_data.hpp"
#include "snap/transform.hpp"

namespace penshape::snap {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(PathData, LinesAbsoluteRelativeAndImplicit) {
  const auto paths = parse_path_data("M10,20 L30 20 h5 v-5 l-1-1 2,2 H0 V1 z m1 1 2 0", 0.1);
  ASSERT_EQ(paths.size(), 2u);
  const std::vector<PointD> want{{10, 20}, {30, 20}, {35, 20}, {35, 15},
                                 {34, 14}, {36, 16}, {0, 16},  {0, 1}};
  EXPECT_EQ(paths[0].points, want);
  EXPECT_TRUE(paths[0].closed);
  // After z the current point is the subpath's start (10, 20): m1 1 is (11, 21), then an
  // implicit relative lineto.
  EXPECT_EQ(paths[1].points, (std::vector<PointD>{{11, 21}, {13, 21}}));
  EXPECT_FALSE(paths[1].closed);
}

TEST(PathData, NumbersWithoutSeparators) {
  // "1.5.5" is 1.5 then .5; "-1-2" is -1 then -2; exponents.
  const auto paths = parse_path_data("M1.5.5L-1-2l1e1,2E-1", 0.1);
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_EQ(paths[0].points, (std::vector<PointD>{{1.5, 0.5}, {-1, -2}, {9, -1.8}}));
}

TEST(PathData, CubicStaysWithinFlatnessOfTheCurve) {
  const PointD p0{0, 0}, p1{0, 100}, p2{100, 100}, p3{100, 0};
  const double flat = 0.05;
  const auto paths = parse_path_data("M0,0 C0,100 100,100 100,0", flat);
  ASSERT_EQ(paths.size(), 1u);
  const auto& pts = paths[0].points;
  EXPECT_EQ(pts.back(), p3);
  // Dense samples of the exact curve are within flat of the polyline.
  for (int i = 0; i <= 1000; ++i) {
    const double t = i / 1000.0, u = 1 - t;
    const PointD b{
        u * u * u * p0.x + 3 * u * u * t * p1.x + 3 * u * t * t * p2.x + t * t * t * p3.x,
        u * u * u * p0.y + 3 * u * u * t * p1.y + 3 * u * t * t * p2.y + t * t * t * p3.y};
    double best = 1e9;
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
      const PointD a = pts[k], c = pts[k + 1];
      const double dx = c.x - a.x, dy = c.y - a.y;
      const double s =
          std::clamp(((b.x - a.x) * dx + (b.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      best = std::min(best, std::hypot(a.x + s * dx - b.x, a.y + s * dy - b.y));
    }
    EXPECT_LE(best, flat + 1e-9) << "t = " << t;
  }
}

TEST(PathData, SmoothAndQuadraticReflectControlPoints) {
  // S after C reflects the second control point: C(0,0 0,10 10,10 10,0) then S 20,-10 20,0 has
  // first control point (10,-10). Its midpoint (t=1/2) is (15, -3.75).
  const auto a = parse_path_data("M0,0 C0,10 10,10 10,0 S20,-10 20,0", 1e-4);
  const auto b = parse_path_data("M0,0 C0,10 10,10 10,0 C10,-10 20,-10 20,0", 1e-4);
  ASSERT_EQ(a[0].points.size(), b[0].points.size());
  for (std::size_t i = 0; i < a[0].points.size(); ++i) {
    EXPECT_NEAR(a[0].points[i].x, b[0].points[i].x, 1e-12);
    EXPECT_NEAR(a[0].points[i].y, b[0].points[i].y, 1e-12);
  }
  // T after Q: Q(0,0 5,10 10,0) T20,0 reflects to (15,-10); the curve's lowest point is y=-5.
  const auto q = parse_path_data("M0,0 Q5,10 10,0 T20,0", 1e-4);
  double min_y = 0;
  for (const PointD& p : q[0].points) min_y = std::min(min_y, p.y);
  EXPECT_NEAR(min_y, -5.0, 1e-3);
}

TEST(PathData, ArcsFollowTheEllipse) {
  // Half of the circle of radius 50 about (50, 0), from (0,0) (angle pi) to (100,0): sweep 1
  // (the angle increases, pi -> 3pi/2 -> 2pi) goes through negative y, sweep 0 through positive y.
  for (const bool sweep : {true, false}) {
    const auto p =
        parse_path_data(std::string("M0,0 A50,50 0 0 ") + (sweep ? "1" : "0") + " 100,0", 0.01);
    ASSERT_EQ(p.size(), 1u);
    for (const PointD& q : p[0].points) {
      EXPECT_NEAR(std::hypot(q.x - 50, q.y), 50.0, 1e-9);
      EXPECT_TRUE(sweep ? q.y <= 1e-9 : q.y >= -1e-9) << q.x << "," << q.y;
    }
    EXPECT_EQ(p[0].points.back(), (PointD{100, 0}));
  }
  // A rotated ellipse (rx 20, ry 10 at 30 degrees): points satisfy its equation about the centre
  // the endpoints fix; large arc from one end of the major axis to the other.
  const double t = 30 * kPi / 180;
  const PointD c{100, 100};
  const PointD s{c.x + 20 * std::cos(t), c.y + 20 * std::sin(t)};
  const PointD e{c.x - 20 * std::cos(t), c.y - 20 * std::sin(t)};
  const auto pts = flatten_arc(s, 20, 10, 30, false, true, e, 0.01);
  for (const PointD& q : pts) {
    const double dx = q.x - c.x, dy = q.y - c.y;
    const double u = std::cos(t) * dx + std::sin(t) * dy, v = -std::sin(t) * dx + std::cos(t) * dy;
    EXPECT_NEAR(u * u / 400 + v * v / 100, 1.0, 1e-9);
  }
  // Radii too small are scaled up (F.6.6): a radius-1 "circle" between points 10 apart is a
  // half circle of radius 5.
  for (const PointD& q : flatten_arc({0, 0}, 1, 1, 0, false, true, {10, 0}, 0.01)) {
    EXPECT_NEAR(std::hypot(q.x - 5, q.y), 5.0, 1e-9);
  }
}

TEST(PathData, ErrorsNameTheOffset) {
  EXPECT_THROW(parse_path_data("L 1 2", 0.1), PathDataError);
  EXPECT_THROW(parse_path_data("M 1 2 L 3", 0.1), PathDataError);
  EXPECT_THROW(parse_path_data("M 1 2 X 3 4", 0.1), PathDataError);
  EXPECT_THROW(parse_path_data("M 0 0 A 1 1 0 2 0 3 3", 0.1), PathDataError);
  try {
    parse_path_data("M 1 2 L 3 x", 0.1);
    FAIL();
  } catch (const PathDataError& e) {
    EXPECT_NE(std::string(e.what()).find("offset 10"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_point_list("1,2 3"), PathDataError);
  EXPECT_EQ(parse_point_list(" 1,2 3 4 "), (std::vector<PointD>{{1, 2}, {3, 4}}));
}

TEST(Transform, ParsesAndComposesLikeSvg) {
  // translate(10,20) scale(2): (1,1) -> (2,2) -> (12,22).
  const Affine m = parse_transform("translate(10,20) scale(2)");
  EXPECT_EQ(m.apply({1, 1}), (PointD{12, 22}));
  EXPECT_TRUE(m.is_similarity());
  EXPECT_DOUBLE_EQ(m.scale(), 2.0);
  // rotate(90 10 10): (20,10) -> (10,20).
  const PointD r = parse_transform("rotate(90,10,10)").apply({20, 10});
  EXPECT_NEAR(r.x, 10, 1e-12);
  EXPECT_NEAR(r.y, 20, 1e-12);
  // matrix(a b c d e f).
  EXPECT_EQ(parse_transform("matrix(1 2 3 4 5 6)").apply({1, 1}), (PointD{9, 12}));
  // skewX(45): (0,1) -> (1,1); not a similarity.
  const Affine k = parse_transform("skewX(45)");
  EXPECT_NEAR(k.apply({0, 1}).x, 1.0, 1e-12);
  EXPECT_FALSE(k.is_similarity());
  EXPECT_FALSE(parse_transform("scale(1,2)").is_similarity());
  // Inverse round trip.
  const Affine a = parse_transform("translate(3 4) rotate(30) scale(0.5)");
  const PointD p = a.inverse().apply(a.apply({7, -2}));
  EXPECT_NEAR(p.x, 7, 1e-12);
  EXPECT_NEAR(p.y, -2, 1e-12);
  EXPECT_THROW(parse_transform("rotate(1,2)"), TransformError);
  EXPECT_THROW(parse_transform("shear(1)"), TransformError);
  EXPECT_THROW(parse_transform("scale(1"), TransformError);
}

} // namespace
} // namespace penshape::snap
