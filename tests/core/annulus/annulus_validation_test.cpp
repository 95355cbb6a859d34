// Bad inputs give InvalidInput naming the problem.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "penshape/core/annulus/online.hpp"
#include "penshape/core/annulus/rotation.hpp"
#include "penshape/core/annulus/translation.hpp"

namespace penshape::annulus {
namespace {

const std::vector<PointD> kSquare{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
const std::vector<PointD> kArrow{{0, 0}, {4, 0}, {2, 1}, {4, 2}, {0, 2}}; // reflex at (2,1)

template <typename F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "no error";
}

TEST(AnnulusValidation, NonConvexTemplateWhereConvexIsRequired) {
  EXPECT_NE(error_of([] { make_convex_template(kArrow); }).find("not convex"), std::string::npos);
  const TemplatePolygon simple = make_simple_template(kArrow);
  EXPECT_FALSE(simple.convex());
  const std::vector<PointD> pts{{1, 1}};
  EXPECT_NE(error_of([&] {
              decide_translation(simple, OuterOffset::kLinearized, 0.1, pts);
            }).find("convex"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              max_cover_rotation(simple, OuterOffset::kLinearized, 0.1, pts);
            }).find("convex"),
            std::string::npos);
  // The on-line decision takes simple templates with the round outer offset only.
  EXPECT_NE(
      error_of([&] { OnlineContainment(simple, OuterOffset::kLinearized, 0.1); }).find("convex"),
      std::string::npos);
  EXPECT_EQ(error_of([&] { OnlineContainment(simple, OuterOffset::kRound, 0.1); }), "no error");
}

TEST(AnnulusValidation, DegenerateTemplates) {
  EXPECT_NE(error_of([] {
              make_convex_template({{0, 0}, {1, 0}});
            }).find("at least 3"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              make_convex_template({{0, 0}, {1, 0}, {2, 0}, {1, 1}});
            }).find("collinear"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              make_convex_template({{0, 0}, {1, 0}, {1, 0}, {0, 1}});
            }).find("equal"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              make_simple_template({{0, 0}, {4, 0}, {4, 4}, {2, -1}});
            }).find("not simple"),
            std::string::npos);
  // A pentagram has only left turns but winds twice.
  std::vector<PointD> star;
  for (int k = 0; k < 5; ++k) {
    const double a = 2 * 3.14159265358979 * 2 * k / 5;
    star.push_back({std::cos(a), std::sin(a)});
  }
  EXPECT_NE(error_of([&] { make_convex_template(star); }), "no error");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_of([&] {
              make_convex_template({{0, 0}, {1, nan}, {0, 1}});
            }).find("not finite"),
            std::string::npos);
  // Clockwise input is accepted and reoriented.
  const TemplatePolygon cw = make_convex_template({{0, 0}, {0, 2}, {2, 2}, {2, 0}});
  EXPECT_EQ(cw.vertices()[1].x, 2.0);
}

TEST(AnnulusValidation, BadPointsAndDelta) {
  const TemplatePolygon sq = make_convex_template(kSquare);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_NE(error_of([&] { decide_translation(sq, OuterOffset::kRound, 0.1, {}); }).find("empty"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              max_cover_translation(sq, OuterOffset::kRound, 0.1, {{1, nan}});
            }).find("point 0 y is not finite"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              min_width_translation(sq, OuterOffset::kRound, {{0, 0}, {inf, 1}});
            }).find("point 1 x"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              decide_translation(sq, OuterOffset::kRound, -1.0, {{0, 0}});
            }).find("negative"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              decide_translation(sq, OuterOffset::kRound, nan, {{0, 0}});
            }).find("delta is not finite"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              decide_translation(sq, OuterOffset::kRound, 1.0, {{1e300, 0}});
            }).find("limit"),
            std::string::npos);
  Limits small;
  small.max_rotation_points = 3;
  EXPECT_NE(error_of([&] {
              min_width_rotation(sq, OuterOffset::kLinearized, {{0, 0}, {1, 0}, {0, 1}, {1, 1}}, {},
                                 {}, small);
            }).find("at most 3"),
            std::string::npos);
  OnlineContainment online(sq, OuterOffset::kRound, 0.1);
  EXPECT_NE(error_of([&] { online.add({nan, 0}); }).find("not finite"), std::string::npos);
}

} // namespace
} // namespace penshape::annulus
