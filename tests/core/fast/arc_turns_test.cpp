// ArcTurns (engine/fast/arc_turns.hpp), the turn checks of the level-set walk's arcs: a proposed
// chord direction outside the cone of the end normals, or a clockwise step, fails the chord, also
// when the interval signs cannot tell and the exact fallback decides. Against hand-derived signs
// and, for random near-parallel integer directions, against 128-bit integer cross products.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include <CGAL/Interval_nt.h>

#include "engine/fast/arc_turns.hpp"
#include "engine/fast/certified.hpp"

namespace penshape {
namespace {

using fast::DPt;
__extension__ typedef __int128 Wide; // exact for products of 31-bit integers

bool turns_ok(DPt u0, DPt u1, DPt from, bool from_is_end, DPt to, bool to_is_end) {
  fast::ArcTurns turns(u0, u1, from, from_is_end, to, to_is_end);
  {
    const fast::UpwardRounding rounding;
    turns.sign_by_intervals();
  }
  return turns.counterclockwise();
}

DPt direction(double degrees) {
  const double a = degrees * M_PI / 180.0;
  return {std::cos(a), std::sin(a)};
}

// The quarter arc from (1, 0) to (0, 1): directions inside it in order pass; one before u0, one
// past u1 or a step back fails (its chords would leave the arc, or cover part of it twice and
// miss another part).
TEST(ArcTurns, ProposedDirectionsMustStayInTheConeInOrder) {
  const DPt u0{1, 0}, u1{0, 1};
  EXPECT_TRUE(turns_ok(u0, u1, u0, true, direction(30), false));
  EXPECT_TRUE(turns_ok(u0, u1, direction(30), false, direction(60), false));
  EXPECT_TRUE(turns_ok(u0, u1, direction(60), false, u1, true));
  EXPECT_TRUE(turns_ok(u0, u1, u0, true, u1, true)); // the end normals are in order by convexity
  EXPECT_FALSE(turns_ok(u0, u1, u0, true, direction(-10), false));            // before u0
  EXPECT_FALSE(turns_ok(u0, u1, u0, true, direction(100), false));            // past u1
  EXPECT_FALSE(turns_ok(u0, u1, u0, true, direction(190), false));            // opposite the cone
  EXPECT_FALSE(turns_ok(u0, u1, direction(60), false, direction(30), false)); // a step back
  EXPECT_FALSE(turns_ok(u0, u1, direction(100), false, u1, true)); // `from` past u1 comes back
}

// from = (1, 1 - e) and to = (1 + e, 1), e = 2^-30: from x to = 1 - (1 - e²) = e² > 0, but each
// product rounds to an interval around 1, so only the exact fallback tells the turn's sign.
TEST(ArcTurns, TurnsTheIntervalsCannotTellAreDecidedExactly) {
  const double e = std::ldexp(1.0, -30);
  const DPt u0{1, 0}, u1{0, 1};
  const DPt a{1, 1 - e}, b{1 + e, 1};
  {
    const fast::UpwardRounding rounding;
    using I = CGAL::Interval_nt<false>;
    const I c = I(a.x) * I(b.y) - I(a.y) * I(b.x);
    ASSERT_TRUE(c.inf() <= 0 && c.sup() >= 0) << "the intervals decide: the test misses its aim";
  }
  EXPECT_TRUE(turns_ok(u0, u1, a, false, b, false));
  EXPECT_FALSE(turns_ok(u0, u1, b, false, a, false)); // e² clockwise
  // At the cone's side u0 = (1, 1 - e): a hair before it is outside, a hair after inside.
  EXPECT_FALSE(turns_ok(a, u1, a, true, {1 + e, 1 - e}, false)); // a x to = -(1 - e) e
  EXPECT_TRUE(turns_ok(a, u1, a, true, {1 + e, 1}, false));
}

// Random integer directions (|coordinates| <= 2^30 + 6), many near-parallel near the diagonal so
// that the products (up to 2^61) round and the intervals straddle zero; expected signs from exact
// 128-bit integer cross products.
TEST(ArcTurns, MatchIntegerCrossProducts) {
  std::mt19937_64 rng(29);
  std::uniform_int_distribution<std::int64_t> big(-(std::int64_t{1} << 30), std::int64_t{1} << 30);
  std::uniform_int_distribution<std::int64_t> small(-3, 3);
  using I2 = std::pair<std::int64_t, std::int64_t>;
  const auto cross = [](I2 u, I2 w) {
    return static_cast<Wide>(u.first) * w.second - static_cast<Wide>(u.second) * w.first;
  };
  // cross(u, u + (k, k)) = (u.x - u.y) k: tiny for u near the diagonal, whose products are ~2^60.
  const auto near = [&](I2 u) {
    const std::int64_t k = small(rng);
    return I2{u.first + k, u.second + k};
  };
  const auto d = [](I2 u) {
    return DPt{static_cast<double>(u.first), static_cast<double>(u.second)};
  };
  int accepted = 0, rejected = 0, close_calls = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::int64_t x = big(rng);
    const I2 u0 = i % 3 == 0 ? I2{x, x + small(rng)} : I2{x, big(rng)};
    I2 u1{big(rng), big(rng)};
    if (i % 3 == 0) u1 = near(u0);
    if (cross(u0, u1) <= 0) continue; // a convex vertex's normals turn counterclockwise
    const I2 to = i % 2 == 0 ? near(i % 4 == 0 ? u0 : u1) : I2{big(rng), big(rng)};
    const I2 from = i % 5 < 2 ? near(to) : u0;
    const bool from_is_end = from == u0;
    const bool expected =
        cross(u0, to) >= 0 && cross(to, u1) >= 0 && (from_is_end || cross(from, to) >= 0);
    EXPECT_EQ(turns_ok(d(u0), d(u1), d(from), from_is_end, d(to), false), expected)
        << "u0 " << u0.first << "," << u0.second << " u1 " << u1.first << "," << u1.second;
    (expected ? accepted : rejected) += 1;
    const Wide m = std::max({cross(u0, to), -cross(u0, to), cross(to, u1), -cross(to, u1)});
    close_calls += m < (Wide{1} << 12) ? 1 : 0;
  }
  EXPECT_GT(accepted, 100);
  EXPECT_GT(rejected, 100);
  EXPECT_GT(close_calls, 100); // turns far below the products' rounding (2^9 or more)
}

} // namespace
} // namespace penshape
