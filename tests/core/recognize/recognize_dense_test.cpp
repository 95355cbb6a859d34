// Dense strokes: the $1 logs resampled to 1 kHz (one sample per millisecond, as a fast tablet
// sends them) meet the same targets as the logs, every snap's thinned certificate holds against
// a brute-force Hausdorff estimate on the ORIGINAL dense samples, thinning changes few answers,
// and the live recognizer's pen-up answer agrees with recognize() at 1 kHz.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "penshape/core/live_recognizer.hpp"
#include "penshape/core/recognize.hpp"
#include "test_support.hpp"

namespace penshape {
namespace {

using test::kNonShapes;
using test::kShapeTargets;

TEST(RecognizeDense, ConfusionTableAndTargetsAtOneKilohertz) {
  const std::vector<test::Gesture> gestures = test::all_dollar_gestures();
  ASSERT_EQ(gestures.size(), test::dollar_gesture_count());
  std::map<std::string, std::map<std::string, int>> confusion;
  int shapes = 0, shapes_ok = 0, non_shapes = 0, non_shape_snaps = 0, checked = 0;
  std::size_t samples = 0;
  for (std::size_t i = 0; i < gestures.size(); ++i) {
    const test::Gesture& g = gestures[i];
    const std::vector<StrokePoint> dense = test::at_one_khz(g.points);
    ASSERT_GT(dense.size(), g.points.size()) << g.file;
    samples += dense.size();
    const Recognition r = recognize(dense);
    const std::string got = to_string(r.shape);
    ++confusion[g.kind][got];
    if (kShapeTargets.contains(g.kind)) {
      ++shapes;
      if (kShapeTargets.at(g.kind).contains(got)) ++shapes_ok;
    }
    if (kNonShapes.contains(g.kind)) {
      ++non_shapes;
      if (r.shape != ShapeClass::kFreeform) ++non_shape_snaps;
    }
    if (r.shape == ShapeClass::kFreeform) {
      EXPECT_FALSE(r.certificate.certified) << g.file;
      continue;
    }
    ASSERT_TRUE(r.certificate.certified) << g.file;
    EXPECT_LE(r.certificate.bound, r.epsilon) << g.file;
    // The certificate was computed on the thinned path; the brute-force estimate uses every one
    // of the dense samples (every 8th snap: the brute force is quadratic).
    if (i % 8 != 0) continue;
    ++checked;
    const test::IndependentCheck check = test::independent_hausdorff(dense, r, r.epsilon / 20);
    EXPECT_LE(check.hausdorff - check.slack, r.certificate.bound * (1 + 1e-9))
        << g.file << " " << got << ": independent Hausdorff " << check.hausdorff
        << " exceeds the certified bound " << r.certificate.bound;
  }
  test::print_confusion_table(confusion);
  const double shape_rate = static_cast<double>(shapes_ok) / shapes;
  const double snap_rate = static_cast<double>(non_shape_snaps) / non_shapes;
  std::printf(
      "at 1 kHz (%.0f samples per stroke): shapes correct: %d / %d = %.1f%%; non-shape snaps: "
      "%d / %d = %.1f%%; certificates re-checked on the dense samples: %d\n",
      static_cast<double>(samples) / static_cast<double>(gestures.size()), shapes_ok, shapes,
      100 * shape_rate, non_shape_snaps, non_shapes, 100 * snap_rate, checked);
  EXPECT_EQ(shapes, test::dollar_count(540, 135));
  EXPECT_EQ(non_shapes, test::dollar_count(900, 180));
  // Generated: 97.0% and 2.8% measured.
  EXPECT_GE(shape_rate, test::dollar_rate(0.97, 0.95));
  EXPECT_LE(snap_rate, test::dollar_rate(0.02, 0.04));
  EXPECT_GE(checked, test::dollar_count(100, 50));
}

// Thinning adds tau to the bound and drops samples within tau of the kept path: on the logs it
// changes few answers (those near a rule's threshold; the differences are printed).
TEST(RecognizeDense, ThinningChangesFewAnswers) {
  RecognizerConfig unthinned;
  unthinned.thin_tolerance_fraction = 0.0;
  int total = 0, same = 0;
  for (const test::Gesture& g : test::all_dollar_gestures()) {
    const Recognition thin = recognize(g.points);
    const Recognition full = recognize(g.points, unthinned);
    ++total;
    if (thin.shape != full.shape) {
      std::printf("  differs: %s %s -> %s (bounds %.3g -> %.3g, epsilon %.3g)\n", g.file.c_str(),
                  to_string(full.shape), to_string(thin.shape), full.certificate.bound,
                  thin.certificate.bound, thin.epsilon);
      continue;
    }
    ++same;
  }
  std::printf("thinned vs unthinned: %d / %d same class\n", same, total);
  EXPECT_GE(static_cast<double>(same) / total, 0.97);
}

// Pen-up at 1 kHz: the live recognizer fed every dense sample gives recognize()'s class (every
// 8th stroke; the live path at 1 kHz is the daemon's).
TEST(RecognizeDense, LiveFinishAgreesWithRecognizeAtOneKilohertz) {
  const std::vector<test::Gesture> gestures = test::all_dollar_gestures();
  LiveRecognizer live;
  int total = 0, agree = 0;
  for (std::size_t i = 0; i < gestures.size(); i += 8) {
    const std::vector<StrokePoint> dense = test::at_one_khz(gestures[i].points);
    for (const StrokePoint& p : dense) live.add(p);
    const Recognition at_pen_up = live.finish();
    const Recognition offline = recognize(dense);
    ++total;
    if (at_pen_up.shape == offline.shape) ++agree;
    if (at_pen_up.shape != ShapeClass::kFreeform) {
      ASSERT_TRUE(at_pen_up.certificate.certified) << gestures[i].file;
      EXPECT_LE(at_pen_up.certificate.bound, at_pen_up.epsilon) << gestures[i].file;
    }
  }
  std::printf("finish() == recognize() at 1 kHz: %d / %d\n", agree, total);
  EXPECT_GE(static_cast<double>(agree) / total, 0.97);
}

TEST(RecognizeDense, ThinToleranceFractionIsValidated) {
  const std::vector<StrokePoint> s{{0, 0, 0}, {20, 0, 0.02}};
  for (const double bad : {-0.01, 0.3, double{NAN}, double{INFINITY}}) {
    RecognizerConfig c;
    c.thin_tolerance_fraction = bad;
    EXPECT_THROW(recognize(s, c), InvalidInput) << bad;
  }
  RecognizerConfig off;
  off.thin_tolerance_fraction = 0.0;
  EXPECT_EQ(recognize(s, off).shape, ShapeClass::kSegment);
  EXPECT_EQ(recognize(s).shape, ShapeClass::kSegment);
}

// A straight stroke sampled every 0.01 units with a 0.3-unit bump of one sample: the bump is
// farther than tau from the chord, so thinning keeps it and the certified bound still covers
// the true distance (the bump's height) to the fitted segment.
TEST(RecognizeDense, ThinningKeepsWhatMatters) {
  std::vector<StrokePoint> s;
  for (int i = 0; i <= 10000; ++i) {
    const double x = 0.01 * i;
    s.push_back({x, i == 5000 ? 3.0 : 0.0, 1e-3 * i});
  }
  const Recognition r = recognize(s);
  ASSERT_EQ(r.shape, ShapeClass::kSegment);
  ASSERT_EQ(r.params.vertices.size(), 2U);
  // The bump's apex is at distance >= 3 - |segment's y there| from the segment; the bound must
  // be at least the apex's distance to the segment (computed here independently).
  const PointD a = r.params.vertices[0], b = r.params.vertices[1];
  const PointD apex{50.0, 3.0};
  const double vx = b.x - a.x, vy = b.y - a.y;
  double t = ((apex.x - a.x) * vx + (apex.y - a.y) * vy) / (vx * vx + vy * vy);
  t = std::clamp(t, 0.0, 1.0);
  const double apex_distance = std::hypot(apex.x - a.x - t * vx, apex.y - a.y - t * vy);
  EXPECT_GE(r.certificate.bound, apex_distance);
}

} // namespace
} // namespace penshape
