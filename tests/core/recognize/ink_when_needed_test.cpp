// StrokeInput::ink_when_needed: an ink polygon still being built when recognition starts. It must
// be used exactly as a given ink (a bulging ink refuses the circle its path certifies), its
// errors must be recognize()'s and StrokeGrouper::add()'s when Q is read, and a refused stroke is
// not added; an answer that reads no Q (freeform, a union of strokes) never asks for it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "penshape/core/group_recognize.hpp"
#include "penshape/core/ink.hpp"
#include "penshape/core/recognize.hpp"

namespace penshape {
namespace {

// A circle of radius 60 drawn with a pen of radius 2, pressed hard (radius `bulge`) over a
// quarter of it when bulge > 0.
std::vector<InkSample> circle_stroke(double bulge) {
  std::vector<InkSample> s;
  const int n = 400;
  for (int k = 0; k <= n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    const double r = bulge > 0 && std::abs(t - 1.0) < 0.25 ? bulge : 2.0;
    s.push_back({100 + 60 * std::cos(t), 80 + 60 * std::sin(t), r});
  }
  return s;
}

StrokeInput path_of(const std::vector<InkSample>& s, double t0 = 0) {
  StrokeInput input;
  for (std::size_t i = 0; i < s.size(); ++i) {
    input.samples.push_back({s[i].x, s[i].y, t0 + 0.002 * static_cast<double>(i)});
  }
  input.pen_radius = 2.0;
  return input;
}

TEST(InkWhenNeeded, CertifiesOnTheInkAsAGivenInkDoes) {
  for (const double bulge : {0.0, 14.0}) {
    const std::vector<InkSample> s = circle_stroke(bulge);
    const InkPolygon ink = ink_polygon(s, InkOptions{.radius_mm = bulge > 0 ? bulge : 2.0});
    StrokeInput given = path_of(s);
    given.ink = &ink;
    StrokeInput later = path_of(s);
    int calls = 0;
    later.ink_when_needed = [&] {
      ++calls;
      return &ink;
    };
    const RecognizerConfig tol10{.pen_radius = 0.0, .tolerance = 10.0}; // 5 radii (issue 23)
    const Recognition a = recognize(given, tol10);
    const Recognition b = recognize(later, tol10);
    EXPECT_GE(calls, 1);
    EXPECT_EQ(b.certificate.method, "ink");
    EXPECT_EQ(a.shape, b.shape);
    EXPECT_EQ(a.certificate.bound, b.certificate.bound);
    // The independent fact: the hard-pressed quarter bulges 12 beyond the circle's ink, so only
    // an ink that was really looked at refuses the circle the path alone certifies.
    EXPECT_EQ(b.shape == ShapeClass::kCircle, bulge == 0.0) << "bulge " << bulge;
  }
}

TEST(InkWhenNeeded, ItsErrorsAreRecognitionErrors) {
  StrokeInput input = path_of(circle_stroke(0));
  input.ink_when_needed = []() -> const InkPolygon* { throw InvalidInput("no ink after all"); };
  EXPECT_THROW((void)recognize(input), InvalidInput);
  input.ink_when_needed = []() -> const InkPolygon* { return nullptr; };
  EXPECT_THROW((void)recognize(input), InvalidInput);
  const InkPolygon empty;
  input.ink_when_needed = [&] { return &empty; };
  EXPECT_THROW((void)recognize(input), InvalidInput);
}

TEST(InkWhenNeeded, AStrokeWhoseInkFailsIsNotAddedToItsGroup) {
  const std::vector<InkSample> s = circle_stroke(0);
  const InkPolygon ink = ink_polygon(s, InkOptions{.radius_mm = 2.0});
  StrokeGrouper grouper;
  StrokeInput first = path_of(s);
  first.ink_when_needed = [&] { return &ink; };
  const GroupUpdate u = grouper.add(first);
  EXPECT_EQ(u.shape.recognition.shape, ShapeClass::kCircle);
  EXPECT_EQ(u.shape.recognition.certificate.method, "ink");

  // Drawn after the grouping's pause: alone, its circle is confirmed on its (failing) ink.
  StrokeInput refused = path_of(s, 10.0);
  refused.ink_when_needed = []() -> const InkPolygon* { throw std::runtime_error("ink failed"); };
  EXPECT_THROW(grouper.add(refused), std::runtime_error);
  EXPECT_EQ(grouper.stroke_count(), 1U);
  ASSERT_EQ(grouper.shapes().size(), 1U);
  EXPECT_EQ(grouper.shapes().front().id, u.shape.id);
}

// What reads no Q does not wait for it: a freeform scribble, and a stroke that completes a union
// (certified on the strokes' paths) with the stroke before it.
TEST(InkWhenNeeded, AnAnswerThatReadsNoInkNeverAsksForIt) {
  int calls = 0;
  auto failing = [&calls]() -> const InkPolygon* {
    ++calls;
    throw std::runtime_error("ink failed");
  };
  StrokeInput scribble;
  for (int k = 0; k < 200; ++k) {
    const double t = 0.31 * k;
    scribble.samples.push_back({50 + 20 * std::sin(t) + 7 * std::sin(5.3 * t),
                                50 + 0.5 * k + 9 * std::cos(3.1 * t), 0.002 * k});
  }
  scribble.pen_radius = 2.0;
  scribble.ink_when_needed = failing;
  EXPECT_EQ(recognize(scribble).shape, ShapeClass::kFreeform);
  EXPECT_EQ(calls, 0);

  // Two halves of one circle: the second completes the circle with the first.
  std::vector<InkSample> s = circle_stroke(0);
  const std::vector<InkSample> first_half(s.begin(), s.begin() + 201);
  const std::vector<InkSample> second_half(s.begin() + 200, s.end());
  const InkPolygon ink = ink_polygon(first_half, InkOptions{.radius_mm = 2.0});
  StrokeGrouper grouper;
  StrokeInput first = path_of(first_half);
  first.ink_when_needed = [&] { return &ink; };
  (void)grouper.add(first);
  StrokeInput second = path_of(second_half, 1.0);
  second.ink_when_needed = failing;
  const GroupUpdate u = grouper.add(second);
  EXPECT_EQ(u.shape.recognition.shape, ShapeClass::kCircle);
  EXPECT_EQ(u.shape.strokes.size(), 2U);
  EXPECT_EQ(calls, 0);
}

} // namespace
} // namespace penshape
