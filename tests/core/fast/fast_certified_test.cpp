// The fast engine's certified predicates and the level-set walk at the edge of their bounds
// (issue 15): distances exactly at a threshold and one ulp away, decided against closed-form
// geometry; cases only the exact fallback can decide; a level set one 2^-20 unit inside or
// outside the clearance (the former 1/4-unit margins could not decide it); and the arc chords'
// derived sagitta bound, which a walk that ignored it would get wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/fast/certified.hpp"
#include "engine/fast/level_set_check.hpp"
#include "engine/fast/segment_index.hpp"

namespace penshape::fast {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The point (5, h) is at distance exactly h from the segment [(0, 0), (10, 0)].
TEST(FastCertified, DistanceAtTheThresholdNeedsAndGetsTheExactFallback) {
  const IPt a{0, 0}, b{10, 0};
  for (const double h : {1000.1, 3.0e9 + 0.5, 0.7071067811865476}) {
    const OnPiece y = at_point(DPt{5.0, h});
    const std::uint64_t before = exact_fallbacks();
    EXPECT_EQ(compare_distance(y, a, b, h), 0) << h;
    EXPECT_GT(exact_fallbacks(), before) << "an interval cannot decide a tie";
    EXPECT_FALSE(closer_than(y, a, b, h));
    EXPECT_FALSE(farther_than(y, a, b, h));
    // One ulp either side is decided, in the right direction.
    EXPECT_TRUE(farther_than(y, a, b, std::nextafter(h, 0.0))) << h;
    EXPECT_TRUE(closer_than(y, a, b, std::nextafter(h, kInf))) << h;
  }
}

// A point of a piece is p + t (q - p) exactly, not its double rounding: here the double
// evaluation lands on the threshold while the exact point is beyond it.
TEST(FastCertified, PiecePointsAreExact) {
  const DPt p{0.0, 1.0}, q{3.0, 1.0 + std::ldexp(1.0, -52)};
  const double t = 1.0 / 3.0; // y = 1 + t 2^-52, strictly between 1 and the next double
  const OnPiece y{p, q, t};
  EXPECT_EQ(p.y + t * (q.y - p.y), 1.0) << "the double evaluation rounds the point down";
  EXPECT_TRUE(farther_than(y, {0, 0}, {10, 0}, 1.0));
  EXPECT_TRUE(closer_than(y, {0, 0}, {10, 0}, std::nextafter(1.0, kInf)));
}

TEST(FastCertified, SegmentSeparationIsStrictAndExact) {
  const double h = 1000.1;
  const OnPiece p0 = at_point(DPt{0.0, h}), p1 = at_point(DPt{10.0, h});
  EXPECT_FALSE(segments_farther_than(p0, p1, {0, 0}, {10, 0}, h)) << "distance equals T";
  EXPECT_TRUE(segments_farther_than(p0, p1, {0, 0}, {10, 0}, std::nextafter(h, 0.0)));
  // Crossing segments are never far apart, whatever their endpoints' distances.
  const OnPiece c0 = at_point(DPt{5.0, -100.0}), c1 = at_point(DPt{5.0, 100.0});
  EXPECT_FALSE(segments_farther_than(c0, c1, {-1000, 0}, {1000, 0}, 0.5));
  // Touching at an endpoint: distance 0.
  EXPECT_FALSE(segments_farther_than(at_point(DPt{10.0, 0.0}), at_point(DPt{20.0, 5.0}), {0, 0},
                                     {10, 0}, 0.0));
}

// A = the triangle (0, 0), (30000, 40000), (0, 40000) (counterclockwise); its slanted edge has
// the unit right normal n = (4, -3)/5, so the level set {d(·, A) = L} contains the segment
// through (15000, 20000) + L n. B is a triangle whose nearest vertex is
// v = (15000, 20000) + 30 (4, -3), at distance 150 from the edge and 150 - L from that
// segment; its other vertices lie 500 farther out along n.
IRing far_triangle() {
  const IPt v{15000 + 120, 20000 - 90};
  const IPt out{v.x + 400, v.y - 300};
  return {v, {out.x - 150, out.y - 200}, {out.x + 150, out.y + 200}};
}

TEST(FastCertified, LevelSetDecidedOneUnitFractionFromTheClearance) {
  const SegmentIndex a({{{0, 0}, {30000, 40000}, {0, 40000}}}, 200);
  const SegmentIndex b({far_triangle()}, 200);
  ASSERT_TRUE(is_certifiable_region(a));
  ASSERT_TRUE(is_certifiable_region(b));
  const double tiny = std::ldexp(1.0, -20);
  // d(level set, B) = 150 - L against the clearance 1.
  EXPECT_TRUE(level_set_avoids({&a, 149.0 - tiny, &b, 1.0, 2.0}, {})) << "1 + 2^-20 > 1";
  EXPECT_FALSE(level_set_avoids({&a, 149.0 + tiny, &b, 1.0, 2.0}, {})) << "1 - 2^-20 < 1";
  EXPECT_FALSE(level_set_avoids({&a, 149.0, &b, 1.0, 2.0}, {})) << "exactly 1 is not > 1";
}

// The arc around the convex corner (1000, 1000) of A = [0, 1000]² is walked as chords, which lie
// inside the circle. B = [1250, 3250] x [1130, 3130]: its nearest point to that vertex is its
// corner, at distance sqrt(250² + 130²) in a direction (27.5°) that no chord of these sizes
// ends at, so the corner faces the middle of a chord. Chords pass up to ~20 units farther from
// it than the arc does: only the derived sagitta bound keeps the walk from accepting a B within
// the clearance.
TEST(FastCertified, ArcChordsAreBoundedByTheirDerivedSagitta) {
  const SegmentIndex a({{{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}}}, 100);
  const SegmentIndex b({{{1250, 1130}, {3250, 1130}, {3250, 3130}, {1250, 3130}}}, 100);
  const double dist = std::sqrt(250.0 * 250.0 + 130.0 * 130.0); // within 2^-44 of the exact
  for (const double max_sagitta : {64.0, 8.0, 1.0}) {
    // Clearance 1: the corner 1 - 2^-30 from the arc must be rejected at every chord size.
    EXPECT_FALSE(
        level_set_avoids({&a, dist - 1.0 + std::ldexp(1.0, -30), &b, 1.0, max_sagitta}, {}))
        << max_sagitta;
    // 1.6 from the arc: chords refined below a sagitta of 1/2 prove it.
    EXPECT_TRUE(level_set_avoids({&a, dist - 1.6, &b, 1.0, max_sagitta}, {})) << max_sagitta;
  }
}

#if defined(__x86_64__) && defined(__SSE2__)
// UpwardRounding rounds SSE arithmetic upwards inside its scope and restores both units after
// it: the SSE mode always, the x87 control word when something in the scope changed it (CGAL's
// fesetround-based code sets both), and only then (its reload is slow).
TEST(FastCertified, UpwardRoundingRestoresBothUnits) {
  const auto x87 = [] {
    unsigned short cw = 0;
    __asm__ volatile("fnstcw %0" : "=m"(cw));
    return cw;
  };
  const unsigned csr = _mm_getcsr();
  const unsigned short cw = x87();
  volatile double one = 1.0, three = 3.0;
  const double nearest = one / three;
  {
    const UpwardRounding rounding;
    EXPECT_GT(one / three, nearest); // upward inside
    EXPECT_EQ(x87(), cw);            // the x87 unit untouched
    // Something in the scope sets the x87 unit to round towards zero.
    const unsigned short changed = static_cast<unsigned short>(cw | 0x0C00U);
    __asm__ volatile("fldcw %0" : : "m"(changed));
    EXPECT_EQ(x87(), changed);
  }
  // The mode bits (the low six are sticky exception flags, which inexact operations set).
  constexpr unsigned kFlags = 0x3FU;
  EXPECT_EQ(_mm_getcsr() & ~kFlags, csr & ~kFlags);
  EXPECT_EQ(x87(), cw);
  EXPECT_EQ(one / three, nearest);
}
#endif

} // namespace
} // namespace penshape::fast
