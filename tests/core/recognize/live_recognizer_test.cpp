// The live recognizer: previews before pen-up, on-line rejection, and agreement with the
// offline recognizer at pen-up.
#include <gtest/gtest.h>

#include <cstdio>

#include "penshape/core/live_recognizer.hpp"
#include "penshape/core/recognize.hpp"
#include "test_support.hpp"

namespace penshape {
namespace {

TEST(LiveRecognizer, AgreesWithOfflineOnTheDollarLogs) {
  const std::vector<test::Gesture> gestures = test::all_dollar_gestures();
  ASSERT_FALSE(gestures.empty());
  LiveRecognizer live;
  int total = 0, agree = 0, shapes = 0, previewed = 0;
  std::size_t refits = 0, samples = 0, reused = 0, online_rejections = 0;
  for (const test::Gesture& g : gestures) {
    bool had_preview = false;
    for (const StrokePoint& p : g.points) {
      live.add(p);
      if (live.preview().shape != ShapeClass::kFreeform) had_preview = true;
    }
    const LiveStats stats = live.stats();
    refits += stats.refits;
    samples += stats.samples;
    online_rejections += stats.online_rejections;
    const Recognition at_pen_up = live.finish();
    reused += live.stats().reused_at_finish;
    const Recognition offline = recognize(g.points);
    ++total;
    if (at_pen_up.shape == offline.shape) ++agree;
    if (g.kind == "circle" || g.kind == "rectangle" || g.kind == "triangle") {
      ++shapes;
      if (had_preview) ++previewed;
    }
    if (at_pen_up.shape != ShapeClass::kFreeform) {
      ASSERT_TRUE(at_pen_up.certificate.certified) << g.file;
      const test::IndependentCheck check =
          test::independent_hausdorff(g.points, at_pen_up, at_pen_up.epsilon / 20);
      EXPECT_LE(check.hausdorff - check.slack, at_pen_up.certificate.bound * (1 + 1e-9)) << g.file;
    }
  }
  std::printf(
      "live vs offline: %d / %d agree (%.1f%%); shapes with a preview before pen-up: "
      "%d / %d; refits per stroke %.2f, samples per stroke %.1f, reused fits per stroke "
      "%.2f, on-line annulus rejections %zu\n",
      agree, total, 100.0 * agree / total, previewed, shapes, static_cast<double>(refits) / total,
      static_cast<double>(samples) / total, static_cast<double>(reused) / total, online_rejections);
  EXPECT_GE(static_cast<double>(agree) / total, 0.97);
  EXPECT_GE(static_cast<double>(previewed) / shapes, 0.9);
  // Not recomputing from scratch: far fewer full fits than samples.
  EXPECT_LT(static_cast<double>(refits), 0.25 * static_cast<double>(samples));
}

TEST(LiveRecognizer, PreviewTracksAGrowingSegmentThenCorner) {
  LiveRecognizer live;
  for (int k = 0; k <= 100; ++k) live.add({2.0 * k, 0.5 * k, 0.01 * k});
  EXPECT_EQ(live.preview().shape, ShapeClass::kSegment);
  for (int k = 1; k <= 100; ++k) live.add({200.0 + 0.5 * k, 50.0 + 2.0 * k, 1 + 0.01 * k});
  EXPECT_EQ(live.preview().shape, ShapeClass::kPolyline);
  const Recognition r = live.finish();
  EXPECT_EQ(r.shape, ShapeClass::kPolyline);
  EXPECT_TRUE(r.certificate.certified);
}

TEST(LiveRecognizer, BadInput) {
  LiveRecognizer live;
  EXPECT_THROW(live.add({NAN, 0, 0}), InvalidInput);
  EXPECT_THROW((void)live.finish(), InvalidInput); // no samples
  live.add({1, 1, 0});
  EXPECT_THROW((void)live.finish(), InvalidInput); // a single point
  RecognizerConfig small;
  small.max_samples = 2;
  LiveRecognizer bounded(small);
  bounded.add({0, 0, 0});
  bounded.add({1, 0, 0});
  EXPECT_THROW(bounded.add({2, 0, 0}), InvalidInput);
}

} // namespace
} // namespace penshape
