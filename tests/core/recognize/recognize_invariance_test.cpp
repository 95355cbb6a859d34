// The recognizer has no unit, no clock and no origin: the $1 logs (or the generated corpus
// without them) scaled by powers of two, timed in other units or untimed, get the same answer
// with the bound scaled alike; moved far from the origin, almost all keep their class (what is
// left is rounding at ties between fits; recognize_bench --invariance prints every transform).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "penshape/core/recognize.hpp"
#include "test_support.hpp"

namespace penshape {
namespace {

using Points = std::vector<StrokePoint>;

// Every fourth gesture: every kind, subject and speed, at a quarter of the run time.
std::vector<test::Gesture> some_gestures() {
  std::vector<test::Gesture> all = test::all_dollar_gestures(), out;
  for (std::size_t i = 0; i < all.size(); i += 4) out.push_back(std::move(all[i]));
  return out;
}

Points each_point(Points p, const std::function<void(StrokePoint&)>& f) {
  for (StrokePoint& q : p) f(q);
  return p;
}

// Scaling by a power of two is exact in floating point: any change is a unit in the recognizer.
TEST(RecognizeInvariance, PowersOfTwoScaleTheAnswerAndNothingElse) {
  for (const test::Gesture& g : some_gestures()) {
    const Recognition drawn = recognize(g.points);
    for (const double k : {1.0 / 64.0, 1024.0}) {
      const Recognition scaled =
          recognize(each_point(g.points, [k](StrokePoint& q) { q.x *= k, q.y *= k; }));
      ASSERT_EQ(to_string(scaled.shape), std::string(to_string(drawn.shape)))
          << g.file << " x" << k;
      EXPECT_EQ(scaled.epsilon, k * drawn.epsilon) << g.file;
      EXPECT_EQ(scaled.certificate.bound, k * drawn.certificate.bound) << g.file;
    }
  }
}

TEST(RecognizeInvariance, TimeUnitsAndMissingTimesChangeNothing) {
  for (const test::Gesture& g : some_gestures()) {
    const Recognition drawn = recognize(g.points);
    const Recognition in_ms = recognize(each_point(g.points, [](StrokePoint& q) { q.t *= 1e3; }));
    const Recognition untimed = recognize(each_point(g.points, [](StrokePoint& q) { q.t = 0; }));
    for (const Recognition* r : {&in_ms, &untimed}) {
      ASSERT_EQ(r->shape, drawn.shape) << g.file;
      EXPECT_EQ(r->certificate.bound, drawn.certificate.bound) << g.file;
    }
  }
}

// Moved by 10^6, the coordinates round differently; fits that tie but for rounding (a minimax
// plateau) must not decide the answer: the refinement keeps only gains beyond rounding
// (kLeastRefineGain). A recognizer that read positions from the origin would fail this.
TEST(RecognizeInvariance, MovedFarAwayAlmostEveryAnswerStays) {
  const std::vector<test::Gesture> gestures = some_gestures();
  int changed = 0;
  for (const test::Gesture& g : gestures) {
    const Recognition drawn = recognize(g.points);
    const Recognition moved =
        recognize(each_point(g.points, [](StrokePoint& q) { q.x += 1e6, q.y -= 1e6; }));
    if (moved.shape != drawn.shape) {
      ++changed;
      std::printf("moved far: %s %s -> %s\n", g.file.c_str(), to_string(drawn.shape),
                  to_string(moved.shape));
    }
    EXPECT_NEAR(moved.epsilon, drawn.epsilon, 1e-6 * drawn.epsilon) << g.file;
  }
  // At most 0.5% (one stroke of the generated corpus's 192).
  const int most = std::max(1, static_cast<int>(gestures.size()) / 200);
  EXPECT_LE(changed, most) << "more than 0.5% changed class";
}

} // namespace
} // namespace penshape
