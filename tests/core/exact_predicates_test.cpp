// The kernel's orientation filter and segment intersection (geometry/exact_predicates.hpp)
// against plain rational arithmetic written here, on the inputs where a filter goes wrong: the
// classic grid of near-collinear double triples (Kettner et al., "Classroom examples of robustness
// problems"), rationals whose doubles are off by an ulp, tiny and huge coordinates, and segments
// that touch, overlap or miss by one ulp. All three point types must give the exact answer.
#include <gtest/gtest.h>

#include <cfenv>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "geometry/exact_predicates.hpp"

namespace penshape::detail {
namespace {

int reference_orientation(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  const Rational det = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return sgn(det);
}

int filtered_orientation(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  return orientation(filtered(a), filtered(b), filtered(c));
}

// (0.5 + i·ulp, 0.5 + j·ulp) against (12, 12) and (24, 24): doubles alone get many signs wrong.
TEST(OrientationFilter, NearCollinearDoubleGridIsExact) {
  const double ulp = std::nextafter(0.5, 1.0) - 0.5;
  const PointD q{12, 12}, r{24, 24};
  int wrong_without_filter = 0;
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const PointD p{0.5 + i * ulp, 0.5 + j * ulp};
      const int truth = reference_orientation(exact(p), exact(q), exact(r));
      ASSERT_EQ(orientation(p, q, r), truth) << i << ' ' << j;
      ASSERT_EQ(orientation(q, r, p), truth) << i << ' ' << j;
      ASSERT_EQ(filtered_orientation(exact(p), exact(q), exact(r)), truth);
      const double naive = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
      wrong_without_filter += (naive > 0) - (naive < 0) != truth;
    }
  }
  EXPECT_GT(wrong_without_filter, 0); // the grid does reach the filter's hard cases
}

// Rationals that are no doubles, nearly collinear: the doubles the filter sees are truncations,
// so the input error term of the bound is what keeps the sign right.
TEST(OrientationFilter, RoundedRationalInputsAreExact) {
  std::mt19937_64 rng(27);
  std::uniform_int_distribution<long> num(-1'000'000, 1'000'000);
  std::uniform_int_distribution<long> den(3, 999);
  int collinear = 0;
  for (int k = 0; k < 20'000; ++k) {
    // a and b random, c = a + t (b - a) + a perturbation far below an ulp of the coordinates.
    ExactPoint a{Rational(num(rng), den(rng)), Rational(num(rng), den(rng))};
    ExactPoint b{Rational(num(rng), den(rng)), Rational(num(rng), den(rng))};
    a.x.canonicalize(), a.y.canonicalize(), b.x.canonicalize(), b.y.canonicalize();
    Rational t(num(rng), 1'000'003);
    t.canonicalize();
    Rational nudge(num(rng) % 3, 1);
    nudge /= Rational(mpz_class(1) << 80);
    ExactPoint c{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) + nudge};
    const int truth = reference_orientation(a, b, c);
    collinear += truth == 0;
    ASSERT_EQ(filtered_orientation(a, b, c), truth) << k;
    ASSERT_EQ(filtered_orientation(b, c, a), truth) << k;
    ASSERT_EQ(orientation(a, b, c), truth) << k;
  }
  EXPECT_GT(collinear, 100);
}

TEST(OrientationFilter, TinyAndHugeCoordinates) {
  for (const double s : {1e-310, 1e-200, 1e-150, 1.0, 1e150, 1e300}) {
    const PointD a{0, 0}, b{s, s}, c{2 * s, std::nextafter(2 * s, 0.0)};
    const int truth = reference_orientation(exact(a), exact(b), exact(c));
    EXPECT_EQ(orientation(a, b, c), truth) << s;
    EXPECT_EQ(filtered_orientation(exact(a), exact(b), exact(c)), truth) << s;
    const PointD d{s, 0}, e{0, s}, f{s / 2, s / 2};
    EXPECT_EQ(orientation(d, e, f), reference_orientation(exact(d), exact(e), exact(f))) << s;
  }
}

bool reference_intersect(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c,
                         const ExactPoint& d) {
  const auto on = [](const ExactPoint& p, const ExactPoint& q, const ExactPoint& r) {
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  const int o1 = reference_orientation(a, b, c), o2 = reference_orientation(a, b, d);
  const int o3 = reference_orientation(c, d, a), o4 = reference_orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) ||
         (o4 == 0 && on(c, d, b));
}

// Segments on a small lattice scaled by an awkward double: touching, overlapping, crossing and
// missing, with every point type.
TEST(SegmentsIntersect, AllPointTypesAgreeWithRationals) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coord(0, 4);
  const double scale = 0.1;
  int meets = 0, proper = 0;
  for (int k = 0; k < 20'000; ++k) {
    PointD p[4];
    for (auto& q : p) q = {coord(rng) * scale, coord(rng) * scale};
    ExactPoint e[4];
    for (int i = 0; i < 4; ++i) e[i] = exact(p[i]);
    const bool truth = reference_intersect(e[0], e[1], e[2], e[3]);
    meets += truth;
    ASSERT_EQ(segments_intersect(p[0], p[1], p[2], p[3]), truth) << k;
    ASSERT_EQ(segments_intersect(e[0], e[1], e[2], e[3]), truth) << k;
    const FilteredPoint f[4] = {filtered(e[0]), filtered(e[1]), filtered(e[2]), filtered(e[3])};
    ASSERT_EQ(segments_intersect(f[0], f[1], f[2], f[3]), truth) << k;
    const bool crosses = segments_cross_properly(p[0], p[1], p[2], p[3]);
    proper += crosses;
    if (crosses) {
      ASSERT_TRUE(truth);
    }
  }
  EXPECT_GT(meets, 1000);
  EXPECT_GT(proper, 100);
}

TEST(SegmentsIntersect, OneUlpApartAndTouching) {
  const PointD a{0, 0}, b{1, 1};
  const double x = 0.3;
  const double y = std::nextafter(0.3, 1.0);
  EXPECT_TRUE(segments_intersect(a, b, PointD{x, x}, PointD{1, 0}));  // touches at (0.3, 0.3)
  EXPECT_FALSE(segments_intersect(a, b, PointD{y, x}, PointD{1, 0})); // one ulp to the right
  EXPECT_FALSE(segments_cross_properly(a, b, PointD{x, x}, PointD{1, 0}));
  EXPECT_TRUE(segments_intersect(a, b, PointD{1, 1}, PointD{2, 2})); // collinear, one end shared
  EXPECT_FALSE(segments_intersect(a, b, PointD{y + 1, y + 1}, PointD{2, 2}));
}

// The 64-bit integer instance (the fast engine's grid points) at coordinates near 2^61, where
// the determinant needs 128 bits: every sign agrees with rationals, and the segment predicates
// work on integer points through it.
struct IntPoint {
  std::int64_t x = 0;
  std::int64_t y = 0;
};
int orientation(IntPoint a, IntPoint b, IntPoint c) {
  return exact_orientation(a.x, a.y, b.x, b.y, c.x, c.y);
}
ExactPoint exact_int(IntPoint p) {
  return {Rational(mpz_class(static_cast<long>(p.x))), Rational(mpz_class(static_cast<long>(p.y)))};
}

TEST(IntegerOrientation, HugeCoordinatesAgreeWithRationals) {
  std::mt19937_64 rng(11);
  const std::int64_t big = std::int64_t{1} << 61;
  std::uniform_int_distribution<std::int64_t> coord(-big, big);
  std::uniform_int_distribution<std::int64_t> nudge(-2, 2);
  int collinear = 0;
  for (int k = 0; k < 5'000; ++k) {
    const IntPoint a{coord(rng), coord(rng)};
    const IntPoint b{coord(rng), coord(rng)};
    // c near the line ab half the time (b - a halved keeps it in range): sign changes by a unit.
    IntPoint c{coord(rng), coord(rng)};
    if (k % 2 == 0) c = {a.x + (b.x - a.x) / 2 + nudge(rng), a.y + (b.y - a.y) / 2};
    const int truth = reference_orientation(exact_int(a), exact_int(b), exact_int(c));
    collinear += truth == 0;
    ASSERT_EQ(orientation(a, b, c), truth) << k;
  }
  EXPECT_GT(collinear, 0);
  const IntPoint a{-big, -big}, b{big, big};
  EXPECT_TRUE(segments_cross_properly(a, b, IntPoint{-big, big}, IntPoint{big, -big}));
  EXPECT_TRUE(segments_intersect(a, b, IntPoint{0, 0}, IntPoint{big, -big})); // touches at 0
  EXPECT_FALSE(segments_cross_properly(a, b, IntPoint{0, 0}, IntPoint{big, -big}));
  EXPECT_FALSE(segments_intersect(a, b, IntPoint{1, 0}, IntPoint{big, -big}));
}

// A FilteredPoint says whether its doubles are the point exactly; only then may equal doubles
// stand for equal coordinates (compare_lex) and the exact-input error bound decide orientations.
TEST(FilteredPoint, DoublesStandForThePointOnlyWhenExact) {
  const ExactPoint grid{Rational(3, 1024), Rational(-5, 2)};
  const FilteredPoint g = filtered(grid);
  EXPECT_TRUE(g.is_double);
  EXPECT_EQ(g.x, 3.0 / 1024);
  EXPECT_EQ(g.y, -2.5);
  // 1/3 and 1/3 + 2^-80 truncate to the same double but are different points.
  const Rational third(1, 3);
  const Rational tiny(mpz_class(1), mpz_class(1) << 80);
  const ExactPoint a{third, Rational(0)};
  const ExactPoint b{third + tiny, Rational(0)};
  const ExactPoint c{third, tiny};
  const FilteredPoint fa = filtered(a), fb = filtered(b), fc = filtered(c);
  EXPECT_FALSE(fa.is_double);
  EXPECT_EQ(fa.x, fb.x);
  EXPECT_EQ(compare_lex(fa, fb), -1);
  EXPECT_EQ(compare_lex(fb, fa), 1);
  EXPECT_EQ(compare_lex(fa, fc), -1); // same x, y decides by its rational
  // Deliberate copies: another object holding the same point must compare equal.
  const ExactPoint a_again = a; // NOLINT(performance-unnecessary-copy-initialization)
  EXPECT_EQ(compare_lex(fa, filtered(a_again)), 0);
  const ExactPoint g_again = grid; // NOLINT(performance-unnecessary-copy-initialization)
  EXPECT_EQ(compare_lex(g, filtered(g_again)), 0);
}

// The limb fast path of to_double_checked against GMP's own reading: mpq_get_d (truncated
// towards zero) and is_double_exactly's GMP checks, on dyadic rationals at the edges of
// the fast path (numerators of 52-54 bits, denominators 2^0 to 2^64, signs, zero) and on others.
TEST(ExactDouble, LimbFastPathAgreesWithGmp) {
  std::mt19937_64 rng(41);
  std::vector<Rational> values{Rational(0), Rational(1), Rational(-1)};
  for (int bits : {1, 52, 53, 54, 64, 65}) {
    for (int k : {0, 1, 10, 62, 63, 64, 65, 200}) {
      mpz_class n = mpz_class(1) << static_cast<mp_bitcnt_t>(bits - 1);
      n += static_cast<unsigned long>(rng() >> 12);
      for (const mpz_class& sn : {n, mpz_class(-n)}) {
        Rational v(sn, mpz_class(1) << static_cast<mp_bitcnt_t>(k));
        v.canonicalize();
        values.push_back(v);
      }
    }
  }
  values.emplace_back(1, 3);
  values.emplace_back(-7, 10);
  values.emplace_back(mpz_class("123456789012345678901234567890"), 1024);
  int fast = 0;
  for (const Rational& v : values) {
    bool exact = false;
    const double d = to_double_checked(v, exact);
    EXPECT_EQ(d, v.get_d()) << v;
    EXPECT_EQ(exact, is_double_exactly(v)) << v; // the flag GMP's checks gave before
    if (exact) {
      EXPECT_EQ(Rational(d), v) << v;
    }
    double limb = 0;
    if (small_dyadic_to_double(v, limb)) {
      ++fast;
      EXPECT_EQ(limb, d) << v;
      EXPECT_TRUE(exact) << v;
    }
  }
  EXPECT_GT(fast, 20); // the fast path is exercised
}

// The quotient fast path against GMP's mpq_get_d, bit for bit, in the two rounding modes the
// code runs in (nearest, and upwards inside the fast engine's interval scopes): random n / d
// below 2^53 (most quotients inexact, half of them overshooting when rounded), exact quotients,
// numerators or denominators at 2^53 - 1 and beyond (the fallback), and quotients too small for
// the fast path.
TEST(ExactDouble, QuotientFastPathIsMpqGetD) {
  std::mt19937_64 rng(7);
  std::vector<Rational> values{Rational(1, 3), Rational(-2, 3), Rational(1929, 15625),
                               Rational(6, 3), Rational(-9, 1), Rational(3, 8)};
  const std::uint64_t top = (std::uint64_t{1} << 53) - 1;
  values.emplace_back(mpz_class(static_cast<unsigned long>(top)), 3);
  values.emplace_back(1, mpz_class(static_cast<unsigned long>(top)));
  values.emplace_back(mpz_class(static_cast<unsigned long>(top + 2)), 7);
  for (int i = 0; i < 20000; ++i) {
    const int nbits = 1 + static_cast<int>(rng() % 53);
    const int dbits = 1 + static_cast<int>(rng() % 53);
    const auto n = static_cast<unsigned long>((rng() >> (64 - nbits)) | 1U);
    const auto d = static_cast<unsigned long>((rng() >> (64 - dbits)) | 1U);
    Rational v{mpz_class(n), mpz_class(d)};
    v.canonicalize();
    values.push_back((i % 2 == 0) ? v : Rational(-v));
  }
  int fast = 0;
  for (const int mode : {FE_TONEAREST, FE_UPWARD}) {
    ASSERT_EQ(std::fesetround(mode), 0);
    for (const Rational& v : values) {
      double q = 0;
      if (small_quotient_to_double(v, q)) {
        ++fast;
        EXPECT_EQ(q, v.get_d()) << v << " mode " << mode;
      }
      bool exact = false;
      EXPECT_EQ(to_double_checked(v, exact), v.get_d()) << v << " mode " << mode;
      EXPECT_EQ(exact, is_double_exactly(v)) << v;
    }
    std::fesetround(FE_TONEAREST);
  }
  EXPECT_GT(fast, 30000); // the fast path is exercised
  double unused = 0;
  EXPECT_FALSE(small_quotient_to_double(Rational(mpz_class(1), mpz_class(1) << 60), unused));
  EXPECT_FALSE(small_quotient_to_double(Rational(mpz_class(top + 2), 7), unused));
}

} // namespace
} // namespace penshape::detail
