// The recognizer on the shared $1 gesture logs (subjects s01..s06, all speeds), or on the
// generated corpus without them: shapes named right, non-shape gestures left as ink, and every
// snap's certificate checked independently.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <set>

#include "made_shapes.hpp"
#include "penshape/core/recognize.hpp"
#include "test_support.hpp"

namespace penshape {
namespace {

using test::kNonShapes;
using test::kShapeTargets;

TEST(RecognizeDollar, ConfusionTableAndTargets) {
  const std::vector<test::Gesture> gestures = test::all_dollar_gestures();
  ASSERT_EQ(gestures.size(), test::dollar_gesture_count())
      << "the shared s01..s06 (6 x 3 x 16 x 10) or the generated corpus";
  std::map<std::string, std::map<std::string, int>> confusion;
  int shapes = 0, shapes_ok = 0, non_shapes = 0, non_shape_snaps = 0, snaps = 0;
  for (const test::Gesture& g : gestures) {
    const Recognition r = recognize(g.points);
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
    // Every snap: certified, and an independent dense Hausdorff estimate of the two paths stays
    // within the certified bound (which must be within epsilon).
    ++snaps;
    ASSERT_TRUE(r.certificate.certified) << g.file;
    EXPECT_LE(r.certificate.bound, r.epsilon) << g.file;
    const test::IndependentCheck check = test::independent_hausdorff(g.points, r, r.epsilon / 20);
    EXPECT_LE(check.hausdorff - check.slack, r.certificate.bound * (1 + 1e-9))
        << g.file << " " << got << ": independent Hausdorff " << check.hausdorff
        << " exceeds the certified bound " << r.certificate.bound;
  }
  // The confusion table: rows are gesture names, columns the classes given.
  test::print_confusion_table(confusion);
  const double shape_rate = static_cast<double>(shapes_ok) / shapes;
  const double snap_rate = static_cast<double>(non_shape_snaps) / non_shapes;
  std::printf(
      "shapes correct: %d / %d = %.1f%%; non-shape snaps: %d / %d = %.1f%%; snaps checked: "
      "%d\n",
      shapes_ok, shapes, 100 * shape_rate, non_shape_snaps, non_shapes, 100 * snap_rate, snaps);
  EXPECT_EQ(shapes, test::dollar_count(540, 135));
  EXPECT_EQ(non_shapes, test::dollar_count(900, 180));
  // Generated: 97.0% and 2.8% measured (bench/recognize_bench prints both corpora).
  EXPECT_GE(shape_rate, test::dollar_rate(0.97, 0.95));
  EXPECT_LE(snap_rate, test::dollar_rate(0.02, 0.04));
}

bool polygon_class(ShapeClass c) {
  return c == ShapeClass::kPolygon || c == ShapeClass::kRegularPolygon;
}

// No corpus holds drawn polygons of 5..8 corners: the real circles made polygons (made_shapes.hpp:
// the writer's wobble, closure and squash kept, corners added) are polygons of as many corners,
// and the circles themselves never are. Both lie within tolerance of a circle; only the turns at
// the corners tell them apart (the sharp-corner rule, recognize.hpp).
TEST(RecognizeDollar, CirclesMadePolygonsArePolygonsAndCirclesStayRound) {
  int circles = 0, circles_polygon = 0, made = 0, made_right = 0, octagons = 0, octagons_right = 0;
  for (const test::Gesture& g : test::all_dollar_gestures()) {
    if (g.kind != "circle") continue;
    ++circles;
    circles_polygon += polygon_class(recognize(g.points).shape) ? 1 : 0;
    for (int n = 5; n <= 8; ++n) {
      const int right =
          cases::is_polygon_of(recognize(cases::made_polygon(g.points, n, 0.5)), n) ? 1 : 0;
      ++made, made_right += right;
      if (n == 8) ++octagons, octagons_right += right;
    }
  }
  std::printf(
      "circles read as polygons: %d / %d; circles made polygons of 5..8: %d / %d right "
      "(octagons %d / %d)\n",
      circles_polygon, circles, made_right, made, octagons_right, octagons);
  ASSERT_EQ(circles, test::dollar_count(180, 45));
  // Three loose circles (s02/medium/circle02, s04/medium/circle02 and circle05) that neither a
  // circle nor an ellipse certifies were regular pentagons until regular polygons had to be
  // turned at too (kMinFittedCornerShare); one more (s02/fast/circle10, a kinked loop) may be.
  EXPECT_LE(circles_polygon, test::dollar_count(1, 0));
  // Measured: 75.7% (545 / 720) on the real circles, 78.9% (142 / 180) generated. Counted by the
  // corner count, the rules before regular polygons had to be turned at made 41% (a regular
  // pentagon's band holds a made octagon: 75% by class alone); turned at, 58%; with shapes giving
  // way to a polygon of more corners the stroke turns at (kMinMissedCornerTurn) and a corner
  // counted once in the plane, 70%; with a sharp polygon's corner that the stroke turns at standing
  // only epsilon / 4 off its neighbours' chord (kMinFlatCornerTurn), 75.7% (generated 73.9
  // -> 78.9%). The made shapes keep a circle's lumps, as large as a corner's standout: a
  // pessimistic stand-in for a polygon drawn as one. At the derived tolerance (0.125 / 0.135 for
  // 0.115 / 0.125): 79.7% (574 / 720) real, 76.1% (137 / 180) generated.
  EXPECT_GE(made_right, test::dollar_rate(0.76, 0.74) * made);
  // Octagons most: a lump flattens one of their corners below epsilon / 2 off its neighbours'
  // chord while the hand still turned there. Measured 70.6% (127 / 180) real (45.6% before), 57.8%
  // (26 / 45) generated; at the derived tolerance 73.3% (132 / 180) real, 48.9% (22 / 45)
  // generated (the looser band holds more of a generated octagon's flattened corners).
  EXPECT_GE(octagons_right, test::dollar_rate(0.70, 0.45) * octagons);
}

// The ink-level claim on a sample of snaps: points of one ink are within the bound of the other
// ink (spot-checked with the pen disk's boundary directions).
TEST(RecognizeDollar, InkDistanceWithinCertifiedBound) {
  PENSHAPE_SHARED_OR_SKIP(real, "strokes/dollar1");
  int checked = 0;
  for (const char* name :
       {"s02/medium/circle01.xml", "s03/fast/rectangle04.xml", "s04/slow/triangle07.xml",
        "s05/medium/caret02.xml", "s06/fast/v05.xml", "s02/slow/left_sq_bracket03.xml"}) {
    const test::Gesture g = test::read_gesture(test::dollar_dir() / name);
    ASSERT_FALSE(g.points.empty()) << name;
    const Recognition r = recognize(g.points);
    if (r.shape == ShapeClass::kFreeform) continue;
    ++checked;
    const double ink = test::ink_distance_lower_estimate(g.points, r, r.epsilon / 20);
    EXPECT_LE(ink, r.certificate.bound) << name;
  }
  EXPECT_GE(checked, 4);
}

} // namespace
} // namespace penshape
