// recognize_union_detail's UnionUse::kSingleArrowOnly (two strokes apart, kept only as a single
// arrow) skips the other families when no single arrow certifies: checked against the full
// recognition on many two-stroke drawings. Where it answers freeform, the full recognition holds
// no single arrow the grouper could keep (its winner, or the arrow keep_union reads it as);
// elsewhere both answers are the same.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "group_test_support.hpp"
#include "recognize/group/group_classifier.hpp"

namespace penshape {
namespace {

using recognize_detail::recognize_union_detail;
using recognize_detail::UnionUse;
using test::next_start;
using test::Path;
using test::stroke_along;

// A head at `tip`, turned by `turn` radians from +x, barbs `barb` long at `open` radians.
Path head(PointD tip, double turn, double barb, double open) {
  const double a = std::numbers::pi + turn;
  return {{tip.x + barb * std::cos(a + open), tip.y + barb * std::sin(a + open)},
          tip,
          {tip.x + barb * std::cos(a - open), tip.y + barb * std::sin(a - open)}};
}

Path circle(PointD c, double r) {
  Path p;
  for (int k = 0; k <= 48; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 48.0;
    p.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return p;
}

// A shaft from (0, 0) to (end, 0), then `second`.
std::vector<StrokeInput> pair(double end, const Path& second) {
  std::vector<StrokeInput> s{stroke_along({{0, 0}, {end, 0}}, 0.0)};
  s.push_back(stroke_along(second, next_start(s)));
  return s;
}

// Second strokes near a shaft's end: heads at several gaps, turns, barbs and openings (arrows
// with a gap, heads turned away, barbs too long or too short), circles and bars.
std::vector<std::vector<StrokeInput>> drawings() {
  std::vector<std::vector<StrokeInput>> out;
  for (const double end : {60.0, 80.0, 95.0}) {
    for (const double turn : {0.0, 0.25, 0.7}) {
      for (const double barb : {15.0, 40.0, 90.0}) {
        for (const double open : {0.3, 0.6, 1.2}) {
          out.push_back(pair(end, head({100, 0}, turn, barb, open)));
        }
      }
    }
    out.push_back(pair(end, circle({130, 0}, 25)));
    out.push_back(pair(end, {{110, -30}, {110, 30}}));
    out.push_back(pair(end, {{110, 0}, {180, 0}}));
  }
  return out;
}

bool a_single_arrow(const Recognition& r) { return r.shape == ShapeClass::kArrow; }

TEST(UnionUse, ArrowOnlyAgreesWithTheFullRecognitionOnEveryArrow) {
  const RecognizerConfig config;
  int skipped = 0, arrows = 0, others = 0;
  for (const auto& s : drawings()) {
    const auto full = recognize_union_detail(s, config, UnionUse::kAnyShape);
    const auto only = recognize_union_detail(s, config, UnionUse::kSingleArrowOnly);
    if (only.recognition.shape == ShapeClass::kFreeform) {
      ++skipped;
      EXPECT_FALSE(a_single_arrow(full.recognition));
      const auto read = recognize_detail::read_as_arrow(full.recognition);
      EXPECT_FALSE(read && a_single_arrow(read->recognition));
      others += full.recognition.shape != ShapeClass::kFreeform ? 1 : 0;
      continue;
    }
    arrows += a_single_arrow(full.recognition) ? 1 : 0;
    EXPECT_EQ(only.recognition.shape, full.recognition.shape);
    EXPECT_EQ(only.recognition.certificate.bound, full.recognition.certificate.bound);
    EXPECT_EQ(only.recognition.params.vertices, full.recognition.params.vertices);
    EXPECT_EQ(only.rank, full.rank);
  }
  std::printf("skipped %d (of them %d snap as another shape), single arrows %d\n", skipped, others,
              arrows);
  // Both branches are taken, and skipped drawings include ones that snap as another shape.
  EXPECT_GT(skipped, 10);
  EXPECT_GT(arrows, 10);
  EXPECT_GT(others, 5);
}

} // namespace
} // namespace penshape
