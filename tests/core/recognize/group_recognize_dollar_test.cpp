// Grouping on real strokes: $1 rectangles and triangles cut at their corners into 2-4 pieces
// (gaps, overshoots, reversed and reordered pieces, pauses), the rectangles made diamonds and cut
// the same way, the circles made polygons of 5-6 corners and cut the same way, arrows whole and
// cut at the tip, two separate shapes one after the other, two non-shape gestures touching.
// Subjects s02 and s03
// (the benchmark runs every subject), every speed, from the shared corpus when present, else
// from the generated corpus (the same layout; its rectangles, triangles, arrows and non-shapes),
// with counts that follow the corpus at hand (test_support.hpp). Every snap is checked with an
// independent brute-force Hausdorff distance to the union of the pieces.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <numbers>
#include <set>

#include "group_test_support.hpp"
#include "made_shapes.hpp"
#include "multi_stroke_cases.hpp"
#include "recognize/group/group_plausibility.hpp"
#include "test_support.hpp"

namespace penshape {
namespace {

using cases::Gesture;
using cases::Points;

std::vector<Gesture> subjects(const std::filesystem::path& root) {
  std::vector<Gesture> out;
  for (const char* s : {"s02", "s03"}) {
    for (Gesture& g : cases::dollar_gestures(root / s)) out.push_back(std::move(g));
  }
  return out;
}

std::vector<StrokeInput> inputs_of(const std::vector<Points>& strokes) {
  std::vector<StrokeInput> in;
  in.reserve(strokes.size());
  for (const Points& p : strokes) in.push_back({p, nullptr, nullptr, 0.0, {}});
  return in;
}

// Every snap certified, and independently within epsilon of the union of its strokes.
void check_snaps(const std::vector<GroupedShape>& out, const std::vector<StrokeInput>& in,
                 const std::string& what) {
  for (const GroupedShape& g : out) {
    const Recognition& r = g.recognition;
    if (r.shape == ShapeClass::kFreeform) continue;
    ASSERT_TRUE(r.certificate.certified) << what;
    const double h =
        test::union_hausdorff(test::paths_of(in, g.strokes), test::clean_paths(r), r.epsilon / 40);
    EXPECT_LE(h, r.epsilon * 1.0125) << what << ": " << to_string(r.shape);
  }
}

bool one_group_of(const std::vector<GroupedShape>& out, std::size_t n,
                  const std::set<std::string>& classes) {
  return out.size() == 1 && out[0].strokes.size() == n &&
         classes.count(to_string(out[0].recognition.shape)) > 0;
}

struct Tally {
  int right = 0, total = 0;
};

// `g` cut at its corners into 2 to `max_pieces` strokes (variant v): each cut's snaps checked,
// and counted right when it is one group of `classes`.
void tally_cuts(const Gesture& g, std::size_t max_pieces, std::size_t v,
                const std::set<std::string>& classes, Tally& t) {
  for (std::size_t pieces = 2; pieces <= max_pieces; ++pieces) {
    const std::vector<Points> cut = cases::cut_shape(g, pieces, v);
    if (cut.empty()) continue;
    const std::vector<StrokeInput> in = inputs_of(cut);
    const std::vector<GroupedShape> out = recognize_strokes(in);
    check_snaps(out, in, g.file);
    t.right += one_group_of(out, cut.size(), classes) ? 1 : 0;
    ++t.total;
  }
}

TEST(GroupRecognizeDollar, PolygonsCutIntoTwoToFourStrokes) {
  Tally t;
  std::size_t v = 0;
  for (const Gesture& g : subjects(test::dollar_dir())) {
    ++v;
    if (g.kind == "triangle") tally_cuts(g, 3, v, {"triangle"}, t);
    if (g.kind == "rectangle") tally_cuts(g, 4, v, {"rectangle", "square", "quadrilateral"}, t);
  }
  std::printf("polygons in 2-4 strokes: %d / %d right (class and grouping)\n", t.right, t.total);
  ASSERT_EQ(t.total, test::dollar_count(300, 150));
  EXPECT_GE(t.right, test::dollar_rate(0.95, 0.85) * t.total); // generated: 88% measured
}

// No corpus holds diamonds drawn in pieces: the real rectangles made diamonds of 62 and 118
// degrees (made_shapes.hpp), cut at their corners as the rectangles are, are one diamond.
TEST(GroupRecognizeDollar, DiamondsCutIntoTwoToFourStrokes) {
  Tally t;
  int whole = 0, drawn = 0;
  std::size_t v = 0;
  for (const Gesture& g : subjects(test::dollar_dir())) {
    ++v;
    if (g.kind != "rectangle") continue;
    Gesture diamond = g;
    diamond.points = cases::on_corner(g.points, cases::kDiamondAcross);
    whole += recognize(diamond.points).shape == ShapeClass::kDiamond ? 1 : 0;
    ++drawn;
    tally_cuts(diamond, 4, v, {"diamond"}, t);
  }
  std::printf("diamonds in 2-4 strokes: %d / %d right (class and grouping); whole %d / %d\n",
              t.right, t.total, whole, drawn);
  ASSERT_EQ(t.total, test::dollar_count(180, 90));
  // Generated: 79% (71 / 90) measured, as often as whole (23 of their 30 one-stroke diamonds): the
  // generated rectangles' sides bend at a kink, which the stroke turns at as at a corner, so they
  // are read as polygons of 5-6 corners, in pieces too since a group's polygon keeps the corners
  // its strokes turn at (yield_to_more_corners; 94% in pieces when groups were exempt). Real:
  // unchanged (174 / 180 here, 97.8% of all writers' in group_recognize_bench).
  EXPECT_GE(t.right, test::dollar_rate(0.95, 0.75) * t.total);
}

// A circle drawn in 2-4 strokes (cut anywhere: cut_round) is one circle or ellipse. A hand's third
// of a circle read alone wobbles into a polyline, or hooks where it starts into freeform, yet an
// arc bending round the circle's inside fits it (bowed, kMaxBowedCentreOff), or it bends with the
// circle (bent_round_pieces), or a short piece drawn straight lies where the circle itself is
// straight within epsilon / 2 (flat_round_pieces); a D's stem is none of these. Beside it, with
// each of those rules off and with all three.
TEST(GroupRecognizeDollar, CirclesCutIntoTwoToFourStrokes) {
  const std::set<std::string> round{"circle", "ellipse"};
  using Rules = recognize_detail::GroupRules;
  Rules no_bowed, no_flat, no_bent, none;
  no_bowed.bowed_round_pieces = none.bowed_round_pieces = false;
  no_flat.flat_round_pieces = none.flat_round_pieces = false;
  no_bent.bent_round_pieces = none.bent_round_pieces = false;
  std::map<const Rules*, Tally> off;
  Tally with;
  const auto count = [&round](Tally& t, const std::vector<StrokeInput>& in, const Rules& rules) {
    recognize_detail::group_rules() = rules;
    t.right += one_group_of(recognize_strokes(in), in.size(), round) ? 1 : 0;
    ++t.total;
    recognize_detail::group_rules() = Rules{};
  };
  std::size_t v = 0;
  for (const Gesture& g : subjects(test::dollar_dir())) {
    ++v;
    if (g.kind != "circle") continue;
    for (std::size_t pieces = 2; pieces <= 4; ++pieces) {
      const std::vector<Points> cut = cases::cut_round(g.points, pieces, v);
      ASSERT_EQ(cut.size(), pieces) << g.file;
      const std::vector<StrokeInput> in = inputs_of(cut);
      check_snaps(recognize_strokes(in), in, g.file);
      count(with, in, Rules{});
      for (const Rules* r : {&no_bowed, &no_flat, &no_bent, &none}) count(off[r], in, *r);
    }
  }
  std::printf(
      "circles in 2-4 strokes: %d / %d one circle or ellipse; %d without bowed pieces, %d "
      "without flat ones, %d without bent ones, %d without all three\n",
      with.right, with.total, off[&no_bowed].right, off[&no_flat].right, off[&no_bent].right,
      off[&none].right);
  ASSERT_EQ(with.total, test::dollar_count(180, 90));
  // Measured: 93.9% (169 / 180) real, without bowed / flat / bent / all three 162 / 167 / 166 / 28
  // (91.3% of all writers' in group_recognize_bench); generated 100% (90 / 90), 89 / 76 / 90 / 2.
  EXPECT_GE(with.right, test::dollar_rate(0.9, 0.9) * with.total);
  EXPECT_LT(2 * off[&none].right, with.right) << "the cases no longer need the rules";
  EXPECT_LT(off[&no_flat].right, with.right) << "no case needs flat pieces";
}

// No corpus holds polygons of 5-8 corners drawn in pieces: the real circles made polygons
// (made_shapes.hpp; their lumps are the writer's own, so not every one reads as a polygon even
// whole) cut at 1-2 of their corners are one polygon of as many corners about as often as the
// same polygons whole (a polygon missing a corner the hand turned at gives way to one with it,
// in a group's chain too: 76% as often before, heptagons and octagons losing a corner).
TEST(GroupRecognizeDollar, PolygonsOfFiveToEightCornersInPiecesAsWhole) {
  constexpr double kTurn = 0.5;
  const std::set<std::string> polygon{"polygon", "regular_polygon"};
  Tally whole, pieces;
  std::size_t v = 0;
  for (const Gesture& g : subjects(test::dollar_dir())) {
    ++v;
    if (g.kind != "circle") continue;
    for (const int n : {5, 6, 7, 8}) {
      const Points made = cases::made_polygon(g.points, n, kTurn);
      whole.right += cases::is_polygon_of(recognize(made), n) ? 1 : 0;
      ++whole.total;
      const std::vector<std::size_t> corners = cases::made_polygon_corners(made, n, kTurn);
      for (std::size_t k = 2; k <= 3; ++k) {
        const std::vector<Points> cut = cases::cut_at_corners(made, corners, k, v);
        ASSERT_EQ(cut.size(), k) << g.file;
        const std::vector<StrokeInput> in = inputs_of(cut);
        const std::vector<GroupedShape> out = recognize_strokes(in);
        check_snaps(out, in, g.file);
        pieces.right +=
            one_group_of(out, k, polygon) && cases::is_polygon_of(out[0].recognition, n) ? 1 : 0;
        ++pieces.total;
      }
    }
  }
  std::printf("polygons of 5-8 corners: whole %d / %d, in 2-3 pieces %d / %d\n", whole.right,
              whole.total, pieces.right, pieces.total);
  ASSERT_EQ(pieces.total, test::dollar_count(480, 240));
  // Two cuts of each polygon: as often right in pieces as whole, less 10%. Measured 94% as often
  // (349 / 480 against 185 / 240 whole; 88% before a closing stroke running on along the first
  // was an overlap, no crossing), 97% generated (190 / 240 against 98 / 120).
  EXPECT_GE(pieces.right, 0.9 * 2 * whole.right);
}

TEST(GroupRecognizeDollar, ArrowsWholeAndCutAtTheTip) {
  const std::filesystem::path root = test::dollar_dir();
  int whole = 0, cut_right = 0, total = 0;
  std::size_t v = 0;
  for (const Gesture& g : subjects(root)) {
    ++v;
    if (g.kind != "arrow") continue;
    ++total;
    const std::vector<StrokeInput> one = inputs_of({g.points});
    const std::vector<GroupedShape> a = recognize_strokes(one);
    check_snaps(a, one, g.file);
    whole += one_group_of(a, 1, {"arrow"}) ? 1 : 0;
    const std::vector<Points> cut = cases::cut_arrow(g, v);
    ASSERT_EQ(cut.size(), 2u) << g.file;
    const std::vector<StrokeInput> two = inputs_of(cut);
    const std::vector<GroupedShape> b = recognize_strokes(two);
    check_snaps(b, two, g.file);
    cut_right += one_group_of(b, 2, {"arrow"}) ? 1 : 0;
  }
  std::printf("arrows: whole %d / %d, cut at the tip %d / %d\n", whole, total, cut_right, total);
  ASSERT_EQ(total, test::dollar_count(60, 30));
  // The target (the bench over every subject prints the figures).
  EXPECT_GE(whole, 0.95 * total);
  EXPECT_GE(cut_right, 0.95 * total);
}

// Arrows made curved (a 60-degree arc) and bent (a 90-degree elbow), turning left and right by
// turns (made_shapes.hpp): whole and cut at their tip, the head found against the shaft's end.
TEST(GroupRecognizeDollar, CurvedAndBentArrowsWholeAndCut) {
  const std::filesystem::path root = test::dollar_dir();
  const cases::ShaftTurn bends[] = {{std::numbers::pi / 3, 0.5, 1.0},
                                    {std::numbers::pi / 2, 0.6, 0.08}};
  int right = 0, total = 0;
  std::size_t v = 0;
  for (const Gesture& g : subjects(root)) {
    ++v;
    if (g.kind != "arrow") continue;
    for (cases::ShaftTurn bend : bends) {
      bend.turn *= v % 2 == 0 ? 1.0 : -1.0;
      std::size_t tip = 0;
      const Points made = cases::bent_arrow(g.points, bend, &tip);
      const std::vector<StrokeInput> one = inputs_of({made});
      const std::vector<GroupedShape> a = recognize_strokes(one);
      check_snaps(a, one, g.file);
      right += one_group_of(a, 1, {"arrow"}) ? 1 : 0;
      const std::vector<Points> cut = cases::cut_arrow_at(made, tip, v);
      ASSERT_EQ(cut.size(), 2u) << g.file;
      const std::vector<StrokeInput> two = inputs_of(cut);
      const std::vector<GroupedShape> b = recognize_strokes(two);
      check_snaps(b, two, g.file);
      right += one_group_of(b, 2, {"arrow"}) ? 1 : 0;
      total += 2;
    }
  }
  std::printf("curved and bent arrows: %d / %d\n", right, total);
  ASSERT_EQ(total, test::dollar_count(240, 120));
  // Measured 96% (shared corpus) and 82% (generated); with heads sought against the chord only
  // (ArrowRules::heads_at_shaft_end off) 22% and 12%.
  EXPECT_GE(right, test::dollar_rate(0.90, 0.75) * total);
}

TEST(GroupRecognizeDollar, SeparateShapesNeverMerge) {
  const std::filesystem::path root = test::dollar_dir();
  std::vector<const Gesture*> shapes;
  const std::vector<Gesture> all = subjects(root);
  for (const Gesture& g : all) {
    if (g.kind == "rectangle" || g.kind == "triangle" || g.kind == "circle") shapes.push_back(&g);
  }
  int merged = 0, pairs = 0;
  for (std::size_t i = 0; i + 1 < shapes.size(); i += 2) {
    const std::vector<StrokeInput> in =
        inputs_of(cases::side_by_side(shapes[i]->points, shapes[i + 1]->points, 2.0, 0.4));
    const std::vector<GroupedShape> out = recognize_strokes(in);
    check_snaps(out, in, shapes[i]->file);
    ++pairs;
    merged += out.size() == 1 ? 1 : 0;
  }
  std::printf("separate shapes merged: %d / %d\n", merged, pairs);
  ASSERT_EQ(pairs, test::dollar_count(90, 45));
  EXPECT_LE(merged, test::dollar_rate(0.01, 0.05) * pairs); // generated: 1 of 45 measured
}

TEST(GroupRecognizeDollar, NonShapePairsStayInk) {
  const std::filesystem::path root = test::dollar_dir();
  const std::set<std::string>& non = test::kNonShapes;
  std::vector<const Gesture*> g;
  const std::vector<Gesture> all = subjects(root);
  for (const Gesture& x : all) {
    if (non.count(x.kind)) g.push_back(&x);
  }
  int snapped = 0, pairs = 0;
  for (std::size_t i = 0; i + 1 < g.size(); i += 2) {
    const std::vector<StrokeInput> in =
        inputs_of(cases::side_by_side(g[i]->points, g[i + 1]->points, 0.0, 0.4));
    const std::vector<GroupedShape> out = recognize_strokes(in);
    check_snaps(out, in, g[i]->file);
    ++pairs;
    for (const GroupedShape& s : out) {
      snapped += s.strokes.size() == 2 && s.recognition.shape != ShapeClass::kFreeform ? 1 : 0;
    }
  }
  std::printf("non-shape pairs snapped together: %d / %d\n", snapped, pairs);
  ASSERT_EQ(pairs, test::dollar_count(150, 60));
  // Target <= 2% (the bench over every subject prints the figure); this guards against a
  // regression.
  EXPECT_LE(snapped, 0.04 * pairs);
}

} // namespace
} // namespace penshape
