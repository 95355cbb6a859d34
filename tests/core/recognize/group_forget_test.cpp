// StrokeGrouper::forget_unreachable(): a long session keeps grouping with bounded memory. A
// rectangle drawn in 4 sides after 300 unrelated strokes still groups; the samples kept never
// exceed the window add() can reach; and trimming after every stroke changes no answer.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "penshape/core/group_recognize.hpp"

namespace penshape {
namespace {

// A straight stroke from a to b, one sample per 4 px, 10 ms apart, starting at t0.
std::vector<StrokePoint> line(PointD a, PointD b, double t0) {
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  const int n = std::max(3, static_cast<int>(len / 4));
  std::vector<StrokePoint> out;
  for (int k = 0; k <= n; ++k) {
    const double f = static_cast<double>(k) / n;
    out.push_back({a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), t0 + 0.01 * k});
  }
  return out;
}

// 300 strokes, none touching another (each in its own 100 px cell of a 20-wide grid, 40 px
// long, a few pointing different ways), mostly 0.1 s apart (so many stay within the pause
// window), every 25th after a 3 s pause; then the 4 sides of a rectangle far from all of them.
std::vector<StrokeInput> long_session() {
  std::vector<StrokeInput> out;
  double t = 0;
  for (int i = 0; i < 300; ++i) {
    const int row = i / 20; // whole rows of 20 cells
    const PointD o{100.0 * (i % 20), 100.0 * row};
    const PointD d = i % 3 == 0 ? PointD{40, 0} : (i % 3 == 1 ? PointD{0, 40} : PointD{28, 28});
    out.push_back({line(o, {o.x + d.x, o.y + d.y}, t), nullptr, nullptr, 0.0, {}});
    t = out.back().samples.back().t + (i % 25 == 24 ? 3.0 : 0.1);
  }
  const std::vector<PointD> c{{3000, 0}, {3200, 0}, {3200, 120}, {3000, 120}};
  for (std::size_t k = 0; k < 4; ++k) {
    out.push_back({line(c[k], c[(k + 1) % 4], t), nullptr, nullptr, 0.0, {}});
    t = out.back().samples.back().t + 0.3;
  }
  return out;
}

void expect_same(const GroupUpdate& a, const GroupUpdate& b, std::size_t i) {
  EXPECT_EQ(a.shape.id, b.shape.id) << "stroke " << i;
  EXPECT_EQ(a.shape.strokes, b.shape.strokes) << "stroke " << i;
  EXPECT_EQ(a.superseded, b.superseded) << "stroke " << i;
  EXPECT_EQ(a.shape.tidy, b.shape.tidy) << "stroke " << i;
  EXPECT_EQ(a.shape.recognition.shape, b.shape.recognition.shape) << "stroke " << i;
}

TEST(GroupForget, RectangleAfterThreeHundredStrokesStillGroupsWithBoundedMemory) {
  for (const std::size_t max_strokes : {std::size_t{2}, std::size_t{4}, std::size_t{8}}) {
    GroupingConfig config;
    config.max_strokes = max_strokes;
    const std::vector<StrokeInput> s = long_session();
    StrokeGrouper trimmed(config);
    StrokeGrouper whole(config);
    GroupUpdate last;
    for (std::size_t i = 0; i < s.size(); ++i) {
      last = trimmed.add(s[i]);
      trimmed.forget_unreachable();
      expect_same(last, whole.add(s[i]), i);
      EXPECT_LE(trimmed.retained_stroke_count(), 6 * (max_strokes - 1)) << "stroke " << i;
      EXPECT_EQ(trimmed.stroke_count(), i + 1);
    }
    if (max_strokes < 4) continue;
    EXPECT_EQ(last.shape.recognition.shape, ShapeClass::kRectangle) << max_strokes;
    EXPECT_EQ(last.shape.strokes, (std::vector<std::size_t>{300, 301, 302, 303}));
    EXPECT_EQ(last.superseded.size(), 3u); // the three sides, each alone (no open polyline group)
    EXPECT_GE(trimmed.oldest_retained_stroke(), 300u - 6 * max_strokes);
    // The unrelated strokes all snapped alone: each of the 300 is its own answer.
    EXPECT_LE(trimmed.shapes().size(), max_strokes + 6 + 6);
    EXPECT_EQ(whole.shapes().size(), 301u);
  }
}

TEST(GroupForget, NothingAddedNothingKept) {
  StrokeGrouper g;
  g.forget_unreachable();
  EXPECT_EQ(g.retained_stroke_count(), 0u);
  EXPECT_EQ(g.oldest_retained_stroke(), 0u);
  EXPECT_TRUE(g.shapes().empty());
}

} // namespace
} // namespace penshape
