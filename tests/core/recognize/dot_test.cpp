// Dots are strokes (issue 23): a stroke whose samples sit at one position is a `dot` in every
// entry of the recognizer, never an error, and never joins other strokes or stops a batch.
#include <gtest/gtest.h>

#include <vector>

#include "penshape/core/group_recognize.hpp"
#include "penshape/core/live_recognizer.hpp"
#include "penshape/core/recognize.hpp"

namespace penshape {
namespace {

std::vector<StrokePoint> dot_at(double x, double y, int samples) {
  std::vector<StrokePoint> out(static_cast<std::size_t>(samples), StrokePoint{x, y, 0.0});
  for (std::size_t i = 0; i < out.size(); ++i) out[i].t = 0.01 * static_cast<double>(i);
  return out;
}

// A square of side 100 drawn as one stroke, starting at (x, y), from time t0.
std::vector<StrokePoint> square_at(double x, double y, double t0) {
  std::vector<StrokePoint> out;
  const double corners[5][2] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}, {0, 0}};
  for (int side = 0; side < 4; ++side) {
    for (int k = 0; k < 20; ++k) {
      const double f = k / 20.0;
      out.push_back({x + corners[side][0] + f * (corners[side + 1][0] - corners[side][0]),
                     y + corners[side][1] + f * (corners[side + 1][1] - corners[side][1]),
                     t0 + 0.01 * static_cast<double>(out.size())});
    }
  }
  out.push_back({x, y, t0 + 0.01 * static_cast<double>(out.size())});
  return out;
}

void expect_dot(const Recognition& r, double x, double y) {
  EXPECT_EQ(r.shape, ShapeClass::kDot);
  ASSERT_EQ(r.params.vertices.size(), 1U);
  EXPECT_EQ(r.params.vertices[0].x, x);
  EXPECT_EQ(r.params.vertices[0].y, y);
  EXPECT_TRUE(r.certificate.certified);
  EXPECT_EQ(r.certificate.bound, 0.0);
}

TEST(Dot, OneSampleAndManySamplesAtOnePositionAreDots) {
  expect_dot(recognize(dot_at(3, 4, 1)), 3, 4);
  expect_dot(recognize(dot_at(3, 4, 50)), 3, 4);
  RecognizerConfig pen;
  pen.pen_radius = 0.5;
  const Recognition r = recognize(dot_at(-7, 2, 3), pen);
  expect_dot(r, -7, 2);
  EXPECT_EQ(r.pen_radius, 0.5);
  EXPECT_GE(r.epsilon, 0.0);
}

TEST(Dot, NamesAndErrors) {
  EXPECT_STREQ(to_string(ShapeClass::kDot), "dot");
  EXPECT_EQ(shape_class_from_string("dot"), ShapeClass::kDot);
  // Still errors: no sample at all, a non-finite one.
  EXPECT_THROW(recognize(std::vector<StrokePoint>{}), InvalidInput);
  EXPECT_THROW(recognize({{0.0, 1.0 / 0.0, 0.0}}), InvalidInput);
}

TEST(Dot, LiveRecognizerFinishesADotAndGoesOn) {
  LiveRecognizer live;
  for (const StrokePoint& p : dot_at(10, 20, 5)) live.add(p);
  expect_dot(live.finish(), 10, 20);
  for (const StrokePoint& p : square_at(0, 0, 0)) live.add(p);
  EXPECT_EQ(live.finish().shape, ShapeClass::kSquare);
}

TEST(Dot, GrouperKeepsDotsApartAndGoesOn) {
  // A dot drawn right at a square's corner, between two squares: three answers.
  std::vector<StrokeInput> strokes(3);
  strokes[0].samples = square_at(0, 0, 0);
  strokes[1].samples = dot_at(0, 0, 4);
  for (StrokePoint& p : strokes[1].samples) p.t += 1.0;
  strokes[2].samples = square_at(300, 0, 2.0);
  const std::vector<GroupedShape> out = recognize_strokes(strokes);
  ASSERT_EQ(out.size(), 3U);
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kSquare);
  EXPECT_EQ(out[1].strokes, std::vector<std::size_t>{1});
  expect_dot(out[1].recognition, 0, 0);
  EXPECT_TRUE(out[1].tidy.empty());
  EXPECT_EQ(out[2].recognition.shape, ShapeClass::kSquare);
}

TEST(Dot, UnionWithADotIsFreeformAndADotAloneIsADot) {
  std::vector<StrokeInput> strokes(2);
  strokes[0].samples = square_at(0, 0, 0);
  strokes[1].samples = dot_at(50, 50, 2);
  for (StrokePoint& p : strokes[1].samples) p.t += 1.0;
  EXPECT_EQ(recognize_union(strokes).shape, ShapeClass::kFreeform);
  expect_dot(recognize_union(std::span<const StrokeInput>(strokes).subspan(1)), 50, 50);
}

} // namespace
} // namespace penshape
