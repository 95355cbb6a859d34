// The classifier's evidence beyond the band (issue 23 item 2), on synthetic strokes: each rule
// is checked with its threshold switched off (RuleThresholds) beside the shipped one, so the test
// fails when the rule is lost.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "classify_test_support.hpp"
#include "penshape/core/point_arithmetic.hpp"
#include "penshape/core/recognize.hpp"
#include "recognize/classify/classifier.hpp"
#include "recognize/classify/tracing.hpp"
#include "recognize/fitting/prepared_stroke.hpp"

namespace penshape::recognize_detail {
namespace {

using test::chosen;
using test::samples;

// Points every `step` along the polyline through `corners` (the corners included).
std::vector<PointD> walk(const std::vector<PointD>& corners, double step) {
  std::vector<PointD> out{corners.front()};
  for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
    const double len = distance(corners[i], corners[i + 1]);
    const auto n = static_cast<int>(std::ceil(len / step));
    for (int k = 1; k <= n; ++k) {
      out.push_back(corners[i] + (static_cast<double>(k) / n) * (corners[i + 1] - corners[i]));
    }
  }
  return out;
}

const std::vector<PointD> kSquare{{0, 0}, {100, 0}, {100, 100}, {0, 100}, {0, 0}};

TEST(BacktrackShare, AShapeTracedOnceRunsNeverBack) {
  EXPECT_LT(backtrack_share(walk(kSquare, 2), kSquare), 0.01);
  // Started mid-side and closed past the start: still one way round.
  const std::vector<PointD> mid{{50, 0}, {100, 0}, {100, 100}, {0, 100}, {0, 0}, {70, 0}};
  EXPECT_LT(backtrack_share(walk(mid, 2), kSquare), 0.01);
  // Drawn the other way round.
  const std::vector<PointD> back{{0, 0}, {0, 100}, {100, 100}, {100, 0}, {0, 0}};
  EXPECT_LT(backtrack_share(walk(back, 2), kSquare), 0.01);
}

TEST(BacktrackShare, AStemDrawnDownAndUpRunsBackOverIt) {
  // Along a segment of 100, down to its end and back up 50: half of it run backwards.
  const std::vector<PointD> segment{{0, 0}, {0, 100}};
  EXPECT_NEAR(backtrack_share(walk({{0, 0}, {0, 100}, {0, 50}}, 1), segment), 0.5, 0.02);
  // Around the square, then back along its last side: 100 of 400.
  const std::vector<PointD> retraced{{0, 0}, {100, 0}, {100, 100}, {0, 100}, {0, 0}, {0, 100}};
  EXPECT_NEAR(backtrack_share(walk(retraced, 2), kSquare), 0.25, 0.02);
}

TEST(BacktrackShare, StrokesOfAClosedShapeEachRunTheirOwnWay) {
  // The square's left and right halves, both drawn from its top side down to its bottom one: each
  // stroke runs one way, though no path joins them one way round.
  const std::vector<PointD> left = walk({{50, 100}, {0, 100}, {0, 0}, {50, 0}}, 2);
  const std::vector<PointD> right = walk({{50, 100}, {100, 100}, {100, 0}, {50, 0}}, 2);
  EXPECT_LT(backtrack_share({left, right}, kSquare), 0.01);
  // Taken as one path in drawing order, one of them runs back over half the square.
  std::vector<PointD> chained = left;
  chained.insert(chained.end(), right.begin(), right.end());
  EXPECT_GT(backtrack_share(chained, kSquare), 0.4);
  // A stroke that runs back within itself still counts: 100 of 400.
  const std::vector<PointD> stem = walk({{0, 0}, {0, 100}, {0, 0}}, 2);
  EXPECT_NEAR(backtrack_share({left, stem}, kSquare), 0.25, 0.02);
}

TEST(ClassifyRules, ALetterPDrawnInOneStrokeIsNoQuadrilateral) {
  // Down the stem and up again, then a bowl reaching near the stem's foot: a P whose stem is
  // drawn twice, inside a quadrilateral's band at the default tolerance.
  const std::vector<StrokePoint> p =
      samples(walk({{0, 0}, {0, 100}, {0, 0}, {60, 0}, {60, 85}, {0, 85}}, 1));
  RuleThresholds off;
  off.max_backtrack = std::numeric_limits<double>::infinity();
  const ShapeClass without = chosen(p, off);
  EXPECT_NE(without, ShapeClass::kFreeform) << "the case no longer needs the rule";
  EXPECT_EQ(chosen(p, {}), ShapeClass::kFreeform) << to_string(chosen(p, {}));
}

} // namespace
} // namespace penshape::recognize_detail
