// union_tolerance(): the grouper's tolerance of a candidate union, from its strokes' bounding
// boxes, must be choose_tolerance() on all the union's samples bit for bit (the grouper's
// answers depend on it through the touch test). Random strokes of varied size and place, every
// union of up to 4 of them, with the default, a pen radius and a fixed tolerance.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "recognize/group/union_tolerance.hpp"

namespace penshape::recognize_detail {
namespace {

std::vector<StrokePoint> random_stroke(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> place(-5000.0, 5000.0);
  std::uniform_real_distribution<double> scale(0.01, 300.0);
  std::uniform_int_distribution<int> count(1, 40);
  const double cx = place(rng), cy = place(rng), s = scale(rng);
  std::normal_distribution<double> step(0.0, s);
  std::vector<StrokePoint> out;
  double x = cx, y = cy;
  for (int k = count(rng); k-- > 0;) {
    x += step(rng);
    y += step(rng);
    out.push_back({x, y, 0.01 * static_cast<double>(out.size())});
  }
  return out;
}

SampleBox box_of(const std::vector<StrokePoint>& samples) {
  SampleBox b{{samples[0].x, samples[0].y}, {samples[0].x, samples[0].y}};
  for (const StrokePoint& s : samples) {
    b.lo = {std::min(b.lo.x, s.x), std::min(b.lo.y, s.y)};
    b.hi = {std::max(b.hi.x, s.x), std::max(b.hi.y, s.y)};
  }
  return b;
}

void expect_same(const ToleranceChoice& a, const ToleranceChoice& b) {
  EXPECT_EQ(a.size, b.size);
  EXPECT_EQ(a.pen_radius, b.pen_radius);
  EXPECT_EQ(a.epsilon, b.epsilon);
}

TEST(UnionTolerance, EqualsChooseToleranceOnAllSamplesBitForBit) {
  std::mt19937_64 rng(26);
  std::vector<RecognizerConfig> configs(3);
  configs[1].pen_radius = 2.5;
  configs[2].tolerance = 7.0;
  for (int round = 0; round < 200; ++round) {
    std::vector<std::vector<StrokePoint>> strokes(4);
    for (auto& s : strokes) s = random_stroke(rng);
    for (unsigned mask = 1; mask < 16; ++mask) {
      std::vector<StrokePoint> all;
      std::vector<SampleBox> boxes;
      for (std::size_t k = 0; k < strokes.size(); ++k) {
        if ((mask & (1U << k)) == 0) continue;
        all.insert(all.end(), strokes[k].begin(), strokes[k].end());
        boxes.push_back(box_of(strokes[k]));
      }
      for (const RecognizerConfig& config : configs) {
        expect_same(union_tolerance(boxes, config), choose_tolerance(all, config));
      }
    }
  }
}

TEST(UnionTolerance, NoStrokesIsNoSamples) {
  const RecognizerConfig config;
  expect_same(union_tolerance({}, config), choose_tolerance({}, config));
}

} // namespace
} // namespace penshape::recognize_detail
