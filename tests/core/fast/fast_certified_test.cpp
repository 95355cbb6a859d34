// The fast engine's certified predicates and the level-set walk at the edge of their bounds
// (issue 15): distances exactly at a threshold and one ulp away, decided against closed-form
// geometry; cases only the exact fallback can decide; a level set one 2^-20 unit inside or
// outside the clearance (the former 1/4-unit margins could not decide it); and the arc chords'
// derived sagitta bound, which a walk that ignored it would get wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

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

// piece_farther_than first asks each near edge against the piece's midpoint with T plus half the
// piece's length: a long piece whose end alone comes near an edge must still be decided by the
// end, on both sides of T.
TEST(FastCertified, LongPieceIsDecidedAtItsEndNotItsMiddle) {
  const SegmentIndex edge({{{1000, -50}, {1000, 50}, {1010, 0}}}, 64);
  const double h = 10.0 + std::ldexp(1.0, -30); // the piece ends h left of the edge x = 1000
  const OnPiece y0 = at_point(DPt{-5000.0, 0.0}), y1 = at_point(DPt{1000.0 - h, 0.0});
  EXPECT_FALSE(piece_farther_than(edge, y0, y1, h)) << "distance equals T";
  EXPECT_FALSE(piece_farther_than(edge, y0, y1, std::nextafter(h, kInf)));
  EXPECT_TRUE(piece_farther_than(edge, y0, y1, std::nextafter(h, 0.0)));
  // The same piece turned away from the edge: its nearest point is still its end.
  EXPECT_TRUE(piece_farther_than(edge, y1, at_point(DPt{1000.0 - h, -6000.0}), 9.0));
  EXPECT_FALSE(piece_farther_than(edge, y1, at_point(DPt{1000.0 - h, -6000.0}), 11.0));
}

// some_edge_closer with a hint: the hinted edge is tried first, a wrong or stale hint never
// makes the answer wrong, and the hint comes back naming the edge that proved it.
TEST(FastCertified, SomeEdgeCloserHintIsOnlyAHint) {
  // Two squares far apart: edges 0-3 belong to the one at the origin, 4-7 to the far one.
  const SegmentIndex index(
      {{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {{5000, 0}, {5100, 0}, {5100, 100}, {5000, 100}}},
      64);
  const OnPiece near_far_square = at_point(DPt{5050.0, -7.0}); // 7 below edge 4
  std::size_t hint = 0;                                        // an edge of the other square
  EXPECT_TRUE(some_edge_closer(index, near_far_square, 8.0, &hint));
  EXPECT_EQ(hint, 4U);
  hint = 4;
  EXPECT_FALSE(some_edge_closer(index, near_far_square, 7.0, &hint)) << "exactly 7 is not < 7";
  EXPECT_EQ(hint, 4U) << "kept when nothing proved it";
  hint = 99; // out of range: ignored
  EXPECT_TRUE(some_edge_closer(index, at_point(DPt{-3.0, 50.0}), 4.0, &hint));
  EXPECT_EQ(hint, 3U);
  // A hint to an edge that is not closer does not stop the search for one that is.
  hint = 1;
  EXPECT_TRUE(some_edge_closer(index, at_point(DPt{50.0, 103.0}), 4.0, &hint));
  EXPECT_EQ(hint, 2U);
}

// A level set with two components: the first far from B and outside it, the second far from
// ∂B but inside B. A run of pieces proven clear of B carries over only to a piece that starts
// where the run ended; the second component's pieces start elsewhere and must be found inside.
TEST(FastCertified, ClearRunsDoNotCarryOverToAnotherComponent) {
  const SegmentIndex a(
      {{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {{5000, 0}, {5100, 0}, {5100, 100}, {5000, 100}}},
      64);
  // B: a square holding the second square's level set (L = 50) with 500 units to spare.
  const SegmentIndex b({{{4400, -600}, {5700, -600}, {5700, 700}, {4400, 700}}}, 64);
  ASSERT_TRUE(is_certifiable_region(a));
  ASSERT_TRUE(is_certifiable_region(b));
  EXPECT_FALSE(level_set_avoids({&a, 50.0, &b, 1.0, 2.0}, {}));
  // B moved off the second square: both components clear.
  const SegmentIndex off({{{4400, 1000}, {5700, 1000}, {5700, 2300}, {4400, 2300}}}, 64);
  EXPECT_TRUE(level_set_avoids({&a, 50.0, &off, 1.0, 2.0}, {}));
}

// A star-shaped ring around c with radii in [r0, r0 + jag] at n angles (counterclockwise,
// simple by construction).
IRing jagged_star(std::mt19937& rng, IPt c, double r0, double jag, int n) {
  std::uniform_real_distribution<double> radius(r0, r0 + jag);
  IRing ring;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * M_PI * i / n, rr = radius(rng);
    ring.push_back({c.x + std::llround(rr * std::cos(t)), c.y + std::llround(rr * std::sin(t))});
  }
  return ring;
}

// Plain doubles, for the sampling check below (no engine code).
double ring_distance(DPt p, const IRing& ring) {
  double best = kInf;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const DPt a = to_d(ring[i]), b = to_d(ring[(i + 1) % ring.size()]);
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double t =
        std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    best = std::min(best, std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy));
  }
  return best;
}
bool inside_ring(DPt p, const IRing& ring) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const DPt a = to_d(ring[i]), b = to_d(ring[j]);
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
}

// The walk against an independent check on random jagged regions: the level set {d(·, A) = L}
// avoids the clearance c around B exactly when d(·, A) - L keeps one sign on the connected set
// offset(B, c). That set is sampled on a fine grid (d(·, A) is 1-Lipschitz, so the samples'
// range is within the spacing of the true one); cases within twice the spacing of L are
// skipped. Pieces that are neither deep nor far as a whole are decided in parts
// (level_set_check.cpp): both answers must come out right.
TEST(FastCertified, LevelSetWalkAgreesWithSampledDistances) {
  std::mt19937 rng(26);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr double kStep = 1.0;
  int accepted = 0, rejected = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const IRing a_ring = jagged_star(rng, {0, 0}, 300, 150, 40);
    const double level = 40.0 + 80.0 * unit(rng), clearance = 1.0 + 15.0 * unit(rng);
    // B: a small jagged star centred somewhere around A's level set.
    const double angle = 2.0 * M_PI * unit(rng), dist = 300.0 + level + 200.0 * unit(rng);
    const IPt bc{std::llround(dist * std::cos(angle)), std::llround(dist * std::sin(angle))};
    const IRing b_ring = jagged_star(rng, bc, 15.0 + 20.0 * unit(rng), 10.0, 9);
    double lo = kInf, hi = -kInf;
    const double reach = 60.0 + clearance;
    for (double x = static_cast<double>(bc.x) - reach; x <= static_cast<double>(bc.x) + reach;
         x += kStep) {
      for (double y = static_cast<double>(bc.y) - reach; y <= static_cast<double>(bc.y) + reach;
           y += kStep) {
        const DPt z{x, y};
        if (!inside_ring(z, b_ring) && ring_distance(z, b_ring) > clearance) continue;
        const double d = inside_ring(z, a_ring) ? 0.0 : ring_distance(z, a_ring);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      }
    }
    const bool clear = hi < level - 2 * kStep || lo > level + 2 * kStep;
    const bool meets = lo < level - 2 * kStep && hi > level + 2 * kStep;
    if (!clear && !meets) continue;
    const SegmentIndex a({a_ring}, 64), b({b_ring}, 64);
    ASSERT_TRUE(is_certifiable_region(a));
    ASSERT_TRUE(is_certifiable_region(b));
    const bool avoids = level_set_avoids({&a, level, &b, clearance, 2.0}, {});
    ASSERT_EQ(avoids, clear) << "trial " << trial << ": d(., A) on offset(B, c) in [" << lo << ", "
                             << hi << "], L " << level;
    (avoids ? accepted : rejected) += 1;
  }
  EXPECT_GT(accepted, 30);
  EXPECT_GT(rejected, 30);
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
