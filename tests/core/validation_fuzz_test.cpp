// Randomised robustness: the validator agrees with a brute-force O(n²) integer check on random
// small rings, and the text readers survive mutated and truncated input (only ParseError or
// InvalidInput, never a crash).
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_io.hpp"
#include "polygon_gen.hpp"
#include "test_data.hpp"

namespace penshape {
namespace {

struct P {
  long long x, y;
};

long long cross(P o, P a, P b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

int sign(long long v) { return (v > 0) - (v < 0); }

bool on_segment(P a, P b, P c) {
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

bool closed_segments_meet(P a, P b, P c, P d) {
  const int o1 = sign(cross(a, b, c)), o2 = sign(cross(a, b, d));
  const int o3 = sign(cross(c, d, a)), o4 = sign(cross(c, d, b));
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
         (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

// A simple ring in the validator's sense, by brute force.
bool brute_force_simple(const std::vector<P>& r) {
  const std::size_t n = r.size();
  if (n < 3) return false;
  long long area2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const P a = r[i], b = r[(i + 1) % n];
    if (a.x == b.x && a.y == b.y) return false;
    area2 += a.x * b.y - a.y * b.x;
  }
  if (area2 == 0) return false;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const P a = r[i], b = r[(i + 1) % n], c = r[j], d = r[(j + 1) % n];
      const bool adjacent = (i + 1) % n == j || (j + 1) % n == i;
      if (adjacent) {
        // They share one vertex; they must not fold back onto each other.
        const P shared = (i + 1) % n == j ? b : a;
        const P other1 = (i + 1) % n == j ? a : b;
        const P other2 = (i + 1) % n == j ? d : c;
        if (cross(shared, other1, other2) == 0 &&
            (on_segment(shared, other1, other2) || on_segment(shared, other2, other1))) {
          return false;
        }
        continue;
      }
      if (closed_segments_meet(a, b, c, d)) return false;
    }
  }
  return true;
}

TEST(ValidationFuzz, AgreesWithBruteForceOnRandomRings) {
  std::mt19937 rng(2024);
  std::uniform_int_distribution<int> coord(0, 6);
  std::uniform_int_distribution<int> size(3, 8);
  int simple = 0, rejected = 0;
  for (int t = 0; t < 4000; ++t) {
    std::vector<P> pts(static_cast<std::size_t>(size(rng)));
    for (auto& p : pts) p = {coord(rng), coord(rng)};
    Ring ring;
    for (const auto& p : pts)
      ring.push_back({Rational(static_cast<long>(p.x)), Rational(static_cast<long>(p.y))});
    const PolygonSet q{{{ring, {}}}};
    bool valid = true;
    try {
      validate_region(q);
    } catch (const InvalidInput&) {
      valid = false;
    }
    ASSERT_EQ(valid, brute_force_simple(pts)) << "trial " << t;
    (valid ? simple : rejected) += 1;
  }
  EXPECT_GT(simple, 100); // both outcomes are exercised
  EXPECT_GT(rejected, 100);
}

TEST(ValidationFuzz, MutatedPolygonTextNeverCrashes) {
  const std::string base = gen::comb(9, 10.0, 6.0, 40.0).text; // a generated comb
  const std::string wkt =
      "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 8, 8 8, 8 2, 2 2)))";
  std::mt19937 rng(99);
  const std::string alphabet = "0123456789.-+eE/ \n#(),PMOLYGNa\t";
  for (int t = 0; t < 3000; ++t) {
    std::string text = t % 2 ? base : wkt;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      std::uniform_int_distribution<std::size_t> pos(0, text.size() - 1);
      switch (rng() % 3) {
        case 0:
          text[pos(rng)] = alphabet[rng() % alphabet.size()];
          break;
        case 1:
          text.erase(pos(rng), 1 + rng() % 5);
          break;
        default:
          text.resize(pos(rng)); // truncated
          break;
      }
      if (text.empty()) break;
    }
    try {
      const PolygonSet q = read_polygon_text(text);
      validate_region(q);
    } catch (const InvalidInput&) {
      // ParseError is an InvalidInput: expected for most mutations.
    }
  }
}

} // namespace
} // namespace penshape
