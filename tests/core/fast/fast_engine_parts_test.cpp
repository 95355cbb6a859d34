// The fast engine's building blocks against hand-computed geometry: the grid frame is exact,
// the checked Douglas-Peucker copy stays within its tolerance, the level-set primitive accepts
// and rejects exactly around known distances, and regions with holes or several components
// are deconstructed with independently checked solutions.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/engines.hpp"
#include "engine/fast/douglas_peucker.hpp"
#include "engine/fast/grid_frame.hpp"
#include "engine/fast/level_set_check.hpp"
#include "engine/fast/segment_index.hpp"
#include "engine/fast/yes_certificate.hpp"
#include "fast_test_support.hpp"

namespace penshape {
namespace {

using fast::IPt;
using fast::IRing;
using fast::IRings;

DeconstructParams params_of(const Rational& r, const Rational& eps, const Rational& delta) {
  DeconstructParams p;
  p.radius = r;
  p.tolerance = eps;
  p.precision = delta;
  return p;
}

IRing square(std::int64_t x0, std::int64_t y0, std::int64_t side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

TEST(FastEngineParts, GridFrameRoundTripsExactly) {
  PolygonSet q;
  q.polygons.push_back(
      {{{Rational(1, 3), Rational(0)}, {Rational(5), Rational(1, 7)}, {Rational(2), Rational(4)}},
       {}});
  const DeconstructParams p = params_of(1, Rational(1, 10), Rational(1, 80));
  const fast::GridFrame frame(q, p);
  const Rational unit =
      Rational(1) / Rational(mpz_class(1) << static_cast<mp_bitcnt_t>(frame.scale_exponent()));
  for (const auto& v : q.polygons[0].outer) {
    const ExactPoint back = frame.exact(frame.round(v));
    // Rounding to the grid moves each coordinate by at most half a grid unit.
    EXPECT_LE(abs(back.x - v.x), unit / 2);
    EXPECT_LE(abs(back.y - v.y), unit / 2);
    EXPECT_EQ(frame.round(back), frame.round(v));
  }
  // About 2^10 grid units per delta.
  EXPECT_GE(frame.units(p.precision), 1024.0);
  EXPECT_LT(frame.units(p.precision), 2048.0);
}

// The frame's origin is floor((min - margin) * 2^k) on each axis, with the exact least
// coordinate even where two coordinates have the same double (the box is found comparing doubles
// first): here -1 and -1 - 10^-30 (and -2, -2 - 10^-30) tie as doubles, the smaller comes second,
// and the margin makes (-1 - margin) * 2^k an integer, so the 10^-30 moves the floor by one unit.
TEST(FastEngineParts, GridFrameOriginUsesTheExactLeastCoordinate) {
  const Rational tiny(mpz_class(1), mpz_class("1000000000000000000000000000000"));
  const Rational min_x = Rational(-1) - tiny, min_y = Rational(-2) - tiny;
  PolygonSet q;
  q.polygons.push_back({{{Rational(-1), Rational(-2)},
                         {Rational(4), min_y},
                         {Rational(4), Rational(4)},
                         {min_x, Rational(4)}},
                        {}});
  const DeconstructParams p = params_of(1, Rational(1, 2), Rational(1, 16));
  const fast::GridFrame frame(q, p);
  const int k = frame.scale_exponent();
  ASSERT_GE(k, 3); // margin 13/8: (-1 - 13/8) * 2^k is an integer
  const Rational margin = p.radius + p.tolerance + 2 * p.precision;
  const auto origin = [&](const Rational& least) {
    Rational scaled = least - margin;
    mpq_mul_2exp(scaled.get_mpq_t(), scaled.get_mpq_t(), static_cast<mp_bitcnt_t>(k));
    mpz_class f;
    mpz_fdiv_q(f.get_mpz_t(), scaled.get_num_mpz_t(), scaled.get_den_mpz_t());
    Rational back(f);
    mpq_div_2exp(back.get_mpq_t(), back.get_mpq_t(), static_cast<mp_bitcnt_t>(k));
    return back;
  };
  const ExactPoint corner = frame.exact({0, 0});
  EXPECT_EQ(corner.x, origin(min_x));
  EXPECT_EQ(corner.y, origin(min_y));
  EXPECT_NE(origin(min_x), origin(Rational(-1))); // the tie matters
}

// GridFrame::exact builds (v + t) / 2^k in lowest terms directly (no gcd): the same canonical
// rational as the product it replaced, for points on both sides of the frame's origin, zero
// and coordinates with many trailing zero bits; near the origin (v + t in 64 bits: the
// integer path) and 10^15 away from it (the translation t needs more: GMP's path).
TEST(FastEngineParts, GridPointsConvertBackToCanonicalRationals) {
  for (const long far : {0L, 1000000000000000L}) {
    PolygonSet q;
    const Rational fx(far), fy(-far);
    q.polygons.push_back({{{fx - 3, fy - 2}, {fx + 5, fy - 2}, {fx + 1, fy + 4}}, {}});
    for (const int d : {80, 3}) {
      const fast::GridFrame frame(q, params_of(1, Rational(1, 10), Rational(1, d)));
      const int k = frame.scale_exponent();
      const fast::IPt origin = frame.round({fx, fy});
      for (const std::int64_t v :
           {std::int64_t{0}, std::int64_t{1}, std::int64_t{-1}, std::int64_t{4096},
            std::int64_t{-12288}, std::int64_t{777777}}) {
        const fast::IPt g{origin.x + v, origin.y - v};
        const ExactPoint e = frame.exact(g);
        // The grid point's offset from the origin's grid point, as a product of rationals.
        Rational unit = 1;
        if (k >= 0) {
          mpq_div_2exp(unit.get_mpq_t(), unit.get_mpq_t(), static_cast<mp_bitcnt_t>(k));
        } else {
          mpq_mul_2exp(unit.get_mpq_t(), unit.get_mpq_t(), static_cast<mp_bitcnt_t>(-k));
        }
        const ExactPoint o = frame.exact(origin);
        const Rational dx = e.x - o.x, dy = e.y - o.y;
        EXPECT_EQ(dx, Rational(static_cast<long>(v)) * unit);
        EXPECT_EQ(dy, Rational(-static_cast<long>(v)) * unit);
        for (const Rational& c : {e.x, e.y}) {
          Rational canonical = c;
          canonical.canonicalize();
          EXPECT_EQ(mpz_cmp(c.get_num_mpz_t(), canonical.get_num_mpz_t()), 0);
          EXPECT_EQ(mpz_cmp(c.get_den_mpz_t(), canonical.get_den_mpz_t()), 0);
        }
        EXPECT_EQ(frame.round(e), g);
      }
    }
  }
}

// Issue 22: rounding keeps every ring, in the input's vertex order, even a thin triangle whose
// rounded area has the opposite sign and one that collapses to a single grid point; only the
// YES certificate's solid region leaves such polygons out.
TEST(FastEngineParts, GridKeepsEveryRingInItsExactOrientation) {
  const DeconstructParams p = params_of(1, Rational(1, 2), Rational(1, 16));
  const Rational u(1, 1 << 14); // the grid unit for delta = 1/16 (2^10 units per delta)
  auto at = [&](const Rational& x0, const Rational& y0, double gx, double gy) {
    return ExactPoint{x0 + Rational(gx) * u, y0 + Rational(gy) * u};
  };
  PolygonSet q;
  q.polygons.push_back({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}});
  // Counterclockwise exactly (cross = 200 * 0.46875 - 0.875 * 100 > 0); rounded, (0, 0),
  // (200, 1), (100, 0) is clockwise.
  q.polygons.push_back({{at(20, 5, 0, 0), at(20, 5, 200, 0.875), at(20, 5, 100, 0.46875)}, {}});
  // A triangle a tenth of a unit wide: every vertex rounds to the same grid point.
  q.polygons.push_back({{at(30, 5, 0, 0), at(30, 5, 0.125, 0), at(30, 5, 0, 0.125)}, {}});
  ASSERT_TRUE(has_normalized_orientation(q));
  const fast::GridFrame frame(q, p);
  ASSERT_EQ(frame.scale_exponent(), 14);
  const fast::GridInput grid = frame.round(q);
  ASSERT_EQ(grid.rings.size(), 3U);
  EXPECT_EQ(grid.first_ring, (std::vector<std::size_t>{0, 1, 2, 3}));
  const IRing& thin = grid.rings[1];
  ASSERT_EQ(thin.size(), 3U);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(thin[i], frame.round(q.polygons[1].outer[i]));
  EXPECT_LT(fast::twice_area(thin), 0) << "the rounding flips this ring; it must not be reversed";
  EXPECT_EQ(grid.rings[2].size(), 1U) << "a ring that collapses to a point is kept";
  std::vector<std::size_t> left_out;
  const IRings solid = grid.solid_rings(left_out);
  EXPECT_EQ(solid.size(), 1U);
  EXPECT_EQ(left_out, (std::vector<std::size_t>{1, 2}));
  EXPECT_TRUE(grid.has_thin_ring());
}

TEST(FastEngineParts, CheckedSimplificationStaysWithinTolerance) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> jitter(-40, 40);
  // A wobbly circle of 400 vertices, radius 100000 grid units.
  IRing ring;
  for (int i = 0; i < 400; ++i) {
    const double a = 2 * M_PI * i / 400;
    ring.push_back({std::llround(100000 * std::cos(a)) + jitter(rng),
                    std::llround(100000 * std::sin(a)) + jitter(rng)});
  }
  const double tol = 500.0;
  const auto simplified = fast::simplify_rings_checked({ring}, tol);
  ASSERT_TRUE(simplified.has_value());
  const IRing& s = simplified->front();
  EXPECT_LT(s.size(), ring.size() / 2);
  // Independent check: every original vertex is within tol of the simplified ring.
  for (const IPt& v : ring) {
    double best = 1e300;
    for (std::size_t i = 0; i < s.size(); ++i) {
      best = std::min(
          best, fast_test::seg_dist({static_cast<double>(v.x), static_cast<double>(v.y)},
                                    {static_cast<double>(s[i].x), static_cast<double>(s[i].y)},
                                    {static_cast<double>(s[(i + 1) % s.size()].x),
                                     static_cast<double>(s[(i + 1) % s.size()].y)}));
    }
    EXPECT_LE(best, tol);
  }
}

// A = square [0, 1000]², whose level set at 100 is the square [-100, 1100]² with rounded
// corners. B = a square at a known distance from that curve.
TEST(FastEngineParts, LevelSetPrimitiveMatchesKnownDistances) {
  const fast::SegmentIndex a({square(0, 0, 1000)}, 100);
  ASSERT_TRUE(fast::is_certifiable_region(a));
  for (const std::int64_t gap : {10, 3, -3}) {
    // B's left side sits `gap` units beyond the level set x = 1100.
    const fast::SegmentIndex b({square(1100 + gap, 200, 500)}, 100);
    const bool ok = fast::level_set_avoids({&a, 100.0, &b, 1.0, 2.0}, {});
    EXPECT_EQ(ok, gap >= 3) << "gap " << gap;
  }
  // B containing the whole level set (a big square with A's level set inside) is rejected.
  const fast::SegmentIndex big({square(-5000, -5000, 10000)}, 1000);
  EXPECT_FALSE(fast::level_set_avoids({&a, 100.0, &big, 1.0, 2.0}, {}));
  // Near the rounded corner: the corner point of the level set is at (1100/√2 ...) along the
  // diagonal, at distance 100 from (1000, 1000); a B just outside the arc is accepted.
  const std::int64_t c = 1000 + static_cast<std::int64_t>(std::ceil(100 / std::sqrt(2.0))) + 4;
  const fast::SegmentIndex diag({square(c, c, 300)}, 100);
  EXPECT_TRUE(fast::level_set_avoids({&a, 100.0, &diag, 1.0, 1.0}, {}));
}

TEST(FastEngineParts, NonSimpleOrWronglyNestedRingsAreNotCertifiable) {
  // A bow tie crosses itself.
  const fast::SegmentIndex bow({{{0, 0}, {100, 100}, {100, 0}, {0, 100}}}, 10);
  EXPECT_FALSE(fast::is_certifiable_region(bow));
  // A clockwise "hole" outside its outer ring.
  IRing hole = square(500, 500, 10);
  std::reverse(hole.begin(), hole.end());
  const fast::SegmentIndex stray({square(0, 0, 100), hole}, 10);
  EXPECT_FALSE(fast::is_certifiable_region(stray));
  // The same hole inside the outer ring is fine.
  IRing inner = square(40, 40, 10);
  std::reverse(inner.begin(), inner.end());
  const fast::SegmentIndex nested({square(0, 0, 100), inner}, 10);
  EXPECT_TRUE(fast::is_certifiable_region(nested));
}

// rings_are_simple is the kernel's sweep on grid points: each kind of contact it must see, and
// random rings against a brute-force pairwise test.
TEST(FastEngineParts, RingSimplicityFindsEveryContact) {
  const auto simple = [](const IRings& rings) {
    return fast::rings_are_simple(fast::SegmentIndex(rings, 10));
  };
  EXPECT_TRUE(simple({square(0, 0, 100)}));
  // A spike: consecutive edges folding back onto each other.
  EXPECT_FALSE(simple({{{0, 0}, {100, 0}, {100, 100}, {100, 50}, {0, 100}}}));
  // A vertex on another edge of its ring, and two rings touching at one point.
  EXPECT_FALSE(simple({{{0, 0}, {100, 0}, {50, 0}, {50, 100}}}));
  EXPECT_FALSE(simple({{{0, 0}, {100, 0}, {100, 100}, {0, 100}, {50, 0}, {0, 50}}}));
  EXPECT_FALSE(simple({square(0, 0, 100), square(100, 100, 50)}));
  EXPECT_TRUE(simple({square(0, 0, 100), square(101, 100, 50)}));
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::int64_t> coord(0, 12);
  int crossing = 0;
  for (int k = 0; k < 400; ++k) {
    IRing ring;
    for (int i = 0; i < 5; ++i) {
      const IPt p{coord(rng), coord(rng)};
      if (ring.empty() || !(ring.back() == p)) ring.push_back(p);
    }
    if (ring.size() < 3 || ring.front() == ring.back()) continue;
    const std::size_t n = ring.size();
    bool brute = true;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        const IPt a = ring[i], b = ring[(i + 1) % n], c = ring[j], d = ring[(j + 1) % n];
        if ((i + 1) % n == j || (j + 1) % n == i) {
          const IPt far = (i + 1) % n == j ? a : c; // the other end of the earlier edge
          const IPt end = (i + 1) % n == j ? d : b; // the other end of the later edge
          const IPt mid = (i + 1) % n == j ? b : a; // the shared vertex
          const bool folds =
              fast::orientation(far, mid, end) == 0 &&
              (end.x - mid.x) * (mid.x - far.x) + (end.y - mid.y) * (mid.y - far.y) <= 0;
          if (folds) brute = false;
        } else if (detail::segments_intersect(a, b, c, d)) {
          brute = false;
        }
      }
    }
    crossing += !brute;
    ASSERT_EQ(simple({ring}), brute) << k;
  }
  EXPECT_GT(crossing, 50);
}

// The YES certificate on hand-made candidates for Q = [0, 20000]², r = 1000, eps = 500 (grid
// units). P = [t, 20000 - t]² has offset(P, r) reaching r - t outside Q, so (A) needs
// t >= r - eps = 500, and covers Q's corner iff sqrt(2) t <= r + eps, i.e. t <= 1060.
TEST(FastEngineParts, YesCertificateAcceptsExactlyTheValidSquares) {
  const fast::SegmentIndex q({square(0, 0, 20000)}, 250);
  for (const std::int64_t t : {200, 450, 520, 800, 1040, 1080, 1500}) {
    fast::IRegion p{{square(t, t, 20000 - 2 * t), {}}};
    const fast::YesCheckInput in{
        &q, fast::kInputRounding, &q, {{0, 0}}, {1000.0, 1000.0}, {500.0, 500.0}, 16.0};
    const bool valid = t >= 500 + 2 && t <= 1058; // a little slack for the certificate margins
    const bool invalid = t < 500 || t > 1061;
    const bool ok = fast::verify_yes(in, p, {});
    if (valid) {
      EXPECT_TRUE(ok) << "t = " << t;
    }
    if (invalid) {
      EXPECT_FALSE(ok) << "t = " << t;
    }
  }
}

PolygonSet square_set(int x0, int y0, int side) {
  PolygonWithHoles p;
  for (const auto& [x, y] :
       {std::pair{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}}) {
    p.outer.push_back({Rational(x), Rational(y)});
  }
  PolygonSet s;
  s.polygons.push_back(std::move(p));
  return s;
}

void expect_checked_yes(const PolygonSet& q, const DeconstructParams& p, const char* what) {
  const DeconstructResult res = detail::decide_fast(q, p, {}, {});
  ASSERT_EQ(res.answer, Answer::kYes) << what;
  const double r = p.radius.get_d(), eps = p.tolerance.get_d();
  const auto c = fast_test::check_yes(q, res.solution, r, eps, eps / 6);
  EXPECT_LE(c.q_excess, 1e-9) << what;
  EXPECT_LE(c.p_excess, 1e-9) << what;
}

TEST(FastEngineParts, RegionWithAHoleAndTwoComponents) {
  // A 20x20 frame with a 10x10 hole: the hole survives deconstruction at r = 1.
  PolygonSet frame = square_set(0, 0, 20);
  Ring hole;
  for (const auto& [x, y] : {std::pair{5, 5}, {5, 15}, {15, 15}, {15, 5}}) {
    hole.push_back({Rational(x), Rational(y)});
  }
  frame.polygons[0].holes.push_back(hole);
  expect_checked_yes(frame, params_of(1, Rational(1, 2), Rational(1, 16)), "frame with hole");
  // Two squares far apart: P has (at least) two components.
  PolygonSet two = square_set(0, 0, 10);
  two.polygons.push_back(square_set(30, 0, 10).polygons[0]);
  const DeconstructResult res =
      detail::decide_fast(two, params_of(1, Rational(1, 2), Rational(1, 16)), {}, {});
  ASSERT_EQ(res.answer, Answer::kYes);
  EXPECT_GE(res.solution.polygons.size(), 2U);
  expect_checked_yes(two, params_of(1, Rational(1, 2), Rational(1, 16)), "two squares");
}

} // namespace
} // namespace penshape
