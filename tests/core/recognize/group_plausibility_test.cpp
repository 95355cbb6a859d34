// Groups that certify but are not drawn as their shape is drawn in pieces (group_plausibility):
// a T, a row of dashes; and an arrow whose head is drawn apart from its shaft. Each stroke
// keeps its own answer; no union of them snaps.
#include <gtest/gtest.h>

#include <cmath>

#include "group_test_support.hpp"
#include "penshape/core/group_recognize.hpp"

namespace penshape {
namespace {

using test::next_start;
using test::stroke_along;

// Whether some answer covers several strokes and snaps.
bool merged(const std::vector<GroupedShape>& out) {
  for (const GroupedShape& g : out) {
    if (g.strokes.size() > 1 && g.recognition.shape != ShapeClass::kFreeform) return true;
  }
  return false;
}

TEST(GroupPlausibility, ATIsNoPolyline) {
  std::vector<StrokeInput> s{stroke_along({{0, 0}, {120, 0}}, 0.0)};
  s.push_back(stroke_along({{60, 0}, {60, 120}}, next_start(s)));
  const auto out = recognize_strokes(s);
  EXPECT_FALSE(merged(out));
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kSegment);
  EXPECT_EQ(out[1].recognition.shape, ShapeClass::kSegment);
}

TEST(GroupPlausibility, DashesFourMillimetresApartStaySeparate) {
  // 10 mm dashes, 4 mm gaps, a 1 mm pen: the row's epsilon grows with the row, a dash's does not.
  std::vector<StrokeInput> s;
  for (int k = 0; k < 4; ++k) {
    const double x = 14.0 * k;
    s.push_back(stroke_along({{x, 0}, {x + 10, 0.2}}, s.empty() ? 0.0 : next_start(s), 0.5));
  }
  const auto out = recognize_strokes(s);
  EXPECT_FALSE(merged(out));
  EXPECT_EQ(out.size(), 4u);
}

TEST(GroupPlausibility, AHeadDrawnApartMayBeAsLongAsTheShaft) {
  // The shaft, then the head in one stroke, its barbs 0.83 shafts long (people draw a head apart
  // large): an arrow, since the strokes tell the shaft from the head.
  std::vector<StrokeInput> s{stroke_along({{0, 0}, {100, 0}}, 0.0)};
  s.push_back(stroke_along({{30, -45}, {100, 0}, {30, 45}}, next_start(s)));
  const auto out = recognize_strokes(s);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].recognition.shape, ShapeClass::kArrow);
}

} // namespace
} // namespace penshape
