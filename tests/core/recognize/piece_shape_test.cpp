// A clean shape of several pieces (an arrow whose shaft stops short of its tip): its distances,
// sampling and certificates (path, union of strokes, ink) against brute force computed here on
// the pieces alone. Each check fails when the jump between the pieces is taken as a segment.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "group_test_support.hpp"
#include "penshape/core/ink.hpp"
#include "penshape/core/ink_certificate.hpp"
#include "recognize/certify/certified_distance.hpp"
#include "recognize/certify/union_certificate.hpp"

namespace penshape::recognize_detail {
namespace {

using Piece = test::Path;
using test::seg_dist;

// The distance to the union of the pieces, segment by segment.
double to_pieces(PointD p, const std::vector<Piece>& pieces) {
  double best = INFINITY;
  for (const Piece& piece : pieces) best = std::min(best, test::path_dist(p, piece));
  return best;
}

// Every point of the pieces within step / 2 of one of these.
std::vector<PointD> dense(const std::vector<Piece>& pieces, double step) {
  std::vector<PointD> out;
  for (const Piece& piece : pieces) {
    const Piece d = test::dense(piece, step);
    out.insert(out.end(), d.begin(), d.end());
  }
  return out;
}

// An arrow along +x: tail (0, 0), the shaft stopping at (70, 0), tip (100, 0), barbs back to
// (80, +-15). The gap (70..100) is 30 long, far above the epsilon of 6 used below.
ShapeParams gapped_arrow() {
  ShapeParams p;
  p.vertices = {{0, 0}, {100, 0}, {80, 15}, {80, -15}};
  p.shaft_end = PointD{70, 0};
  return p;
}

const std::vector<Piece> kPieces{{{0, 0}, {70, 0}}, {{80, 15}, {100, 0}, {80, -15}}};

TEST(PieceShape, TheCleanShapeIsTwoPiecesWithAJumpBetween) {
  const CleanShape s = clean_shape_of(ShapeClass::kArrow, gapped_arrow());
  ASSERT_EQ(s.jumps.size(), 1u);
  EXPECT_FALSE(s.joined(s.jumps[0]));
  EXPECT_NEAR(s.length(), 70.0 + 2.0 * std::hypot(20.0, 15.0), 1e-9);
  // No sample lies on the jump: every one is on a piece.
  for (const PointD& q : s.sample(1.0)) EXPECT_LE(to_pieces(q, kPieces), 1e-9);
  const std::vector<std::vector<PointD>> split =
      clean_pieces(ShapeClass::kArrow, gapped_arrow(), s.path);
  ASSERT_EQ(split.size(), 2u);
  EXPECT_EQ(split[0], kPieces[0]);
  EXPECT_EQ(split[1], kPieces[1]);
}

TEST(PieceShape, DistancesAreTheLeastOverThePieces) {
  const CleanShape s = clean_shape_of(ShapeClass::kArrow, gapped_arrow());
  const CertifiedShape cs(s);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-40, 140);
  std::vector<PointD> points{{85, 0}, {75, 0}, {90, 1}}; // in the gap: far from the jump's ends
  for (int i = 0; i < 400; ++i) points.push_back({u(rng), u(rng)});
  for (const PointD& p : points) {
    const double truth = to_pieces(p, kPieces);
    EXPECT_NEAR(s.distance_to(p), truth, 1e-9) << p.x << " " << p.y;
    const double up = cs.upper(detail::enclose(p), p);
    EXPECT_GE(up, truth - 1e-9) << p.x << " " << p.y; // truth is rounded, the bound is not
    EXPECT_LE(up, truth + 1e-9) << p.x << " " << p.y;
  }
}

// sup over the shape of the distance to a segment set, against dense sampling of the pieces.
TEST(PieceShape, TheFarthestPointOfTheShapeIsOnAPiece) {
  const CleanShape s = clean_shape_of(ShapeClass::kArrow, gapped_arrow());
  const CertifiedShape cs(s);
  // The strokes: the shaft drawn 2 above its line, the head as it is.
  std::vector<Segment> strokes{{{0, 2}, {70, 2}}, {{80, 15}, {100, 0}}, {{100, 0}, {80, -15}}};
  const SegmentIndex index(strokes, 5.0);
  const double h = 1.0;
  const double bound = cs.farthest_from(index, h);
  double truth = 0.0;
  for (const PointD& q : dense(kPieces, 0.01)) {
    double d = INFINITY;
    for (const Segment& g : strokes) d = std::min(d, seg_dist(q, g.a, g.b));
    truth = std::max(truth, d);
  }
  EXPECT_GE(bound, truth - 0.005); // dense sampling finds the sup within half its step
  EXPECT_LE(bound, truth + h / 2 + 1e-9);
  EXPECT_NEAR(truth, 2.0, 1e-9);
}

// The union certificate of the two strokes that draw the pieces: a small bound for the gapped
// arrow, and none for the arrow whose shaft runs to the tip (its shaft crosses the gap).
TEST(PieceShape, TheUnionCertificateSeesTheGap) {
  const UnionStroke u = prepare_union({{{0, 1}, {35, 0}, {70, 1}}, kPieces[1]}, 0.0);
  const double eps = 6.0;
  const Certificate gapped =
      certify_union(u, clean_shape_of(ShapeClass::kArrow, gapped_arrow()), eps, 1.0);
  EXPECT_TRUE(gapped.certified);
  EXPECT_GE(gapped.bound, 1.0); // the shaft stroke strays by 1
  EXPECT_LE(gapped.bound, 1.0 + eps / 6.0 + 1e-9);
  ShapeParams joined = gapped_arrow();
  joined.shaft_end.reset();
  const Certificate whole = certify_union(u, clean_shape_of(ShapeClass::kArrow, joined), eps, 1.0);
  EXPECT_FALSE(whole.certified);
  // (81.25, 0) in the gap is 11.25 from the shaft's end and from both barbs.
  EXPECT_GE(whole.bound, 11.25);
}

// The ink certificate on Q of the two strokes (pen radius 1): the gapped arrow's ink is within
// the tolerance, the joined arrow's is not (its shaft's ink fills the gap).
TEST(PieceShape, TheInkCertificateSeesTheGap) {
  auto samples = [](const Piece& piece) {
    std::vector<InkSample> out;
    for (const PointD& q : dense({piece}, 0.5)) out.push_back({q.x, q.y, 1.0});
    return out;
  };
  InkOptions options;
  options.radius_mm = 1.0;
  const InkPolygon q = ink_polygon({samples(kPieces[0]), samples(kPieces[1])}, options);
  const double eps = 3.0;
  const Certificate gapped = certify_ink(q, ShapeClass::kArrow, gapped_arrow(), 1.0, eps);
  EXPECT_TRUE(gapped.certified) << gapped.bound;
  ShapeParams joined = gapped_arrow();
  joined.shaft_end.reset();
  const Certificate whole = certify_ink(q, ShapeClass::kArrow, joined, 1.0, eps);
  EXPECT_FALSE(whole.certified) << whole.bound;
}

TEST(PieceShape, AShaftEndIsOnlyASingleArrowsStraightOrBentShaft) {
  ShapeParams curved = gapped_arrow();
  curved.shaft_bulge = 5.0;
  EXPECT_THROW((void)clean_shape_of(ShapeClass::kArrow, curved), InvalidInput);
  ShapeParams nan = gapped_arrow();
  nan.shaft_end = PointD{std::nan(""), 0};
  EXPECT_THROW((void)clean_shape_of(ShapeClass::kArrow, nan), InvalidInput);
  ShapeParams bent = gapped_arrow();
  bent.shaft_bends = {{35, 5}};
  const CleanShape s = clean_shape_of(ShapeClass::kArrow, bent);
  ASSERT_EQ(s.jumps.size(), 1u);
  EXPECT_EQ(s.path[s.jumps[0]].x, 70.0); // the jump leaves the shaft's end
}

} // namespace
} // namespace penshape::recognize_detail
