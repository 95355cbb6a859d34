// The nesting sweep (geometry/ring_nesting) against a brute force written here: every ring's
// first vertex tested against every other ring by exact crossing parity, the innermost
// container being the one with the most containers itself. Random families of disjoint rings
// built by recursive subdivision on an integer lattice (many shared x-coordinates, vertical
// edges, diamonds and triangles beside squares), both orientations; and validate_region on
// well and badly nested sets, with the messages of the pairwise test.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "geometry/ring_nesting.hpp"
#include "penshape/core/deconstruct.hpp"

namespace penshape {
namespace {

// Strictly inside by crossing parity of a horizontal ray (exact; p is never on the ring).
bool inside(const Ring& ring, const ExactPoint& p) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const ExactPoint& a = ring[i];
    const ExactPoint& b = ring[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const Rational x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x) in = !in;
    }
  }
  return in;
}

std::vector<long> brute_parents(const std::vector<Ring>& rings) {
  const std::size_t n = rings.size();
  std::vector<std::vector<bool>> in(n, std::vector<bool>(n, false));
  std::vector<int> depth(n, 0);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < n; ++b) {
      if (a != b && inside(rings[b], rings[a][0])) {
        in[a][b] = true;
        ++depth[a];
      }
    }
  }
  std::vector<long> parent(n, -1);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < n; ++b) {
      if (in[a][b] && (parent[a] < 0 || depth[b] > depth[static_cast<std::size_t>(parent[a])])) {
        parent[a] = static_cast<long>(b);
      }
    }
  }
  return parent;
}

Ring shape(int kind, long x0, long y0, long s, bool reverse) {
  Ring r;
  auto add = [&](long x, long y) { r.push_back({Rational(x), Rational(y)}); };
  if (kind == 0) { // square
    add(x0, y0), add(x0 + s, y0), add(x0 + s, y0 + s), add(x0, y0 + s);
  } else if (kind == 1) { // diamond
    add(x0 + s / 2, y0), add(x0 + s, y0 + s / 2), add(x0 + s / 2, y0 + s), add(x0, y0 + s / 2);
  } else { // triangle with a vertical side, and a dent
    add(x0, y0), add(x0 + s, y0 + s / 2), add(x0 + s / 2, y0 + s / 2), add(x0, y0 + s);
  }
  if (reverse) std::reverse(r.begin(), r.end());
  return r;
}

// Rings inside the box [x0, x0 + s]² (exclusive of its border), recursively, in rows of cells
// with every other row shifted by half a cell (brick layout): a ring's upward ray then often
// meets a sibling's bottom edge before its container's.
void subdivide(std::mt19937& rng, long x0, long y0, long s, int depth, std::vector<Ring>& out) {
  if (s < 16 || depth > 3) return;
  std::uniform_int_distribution<int> count(2, 4), kind(0, 2), coin(0, 1);
  const int k = count(rng);
  const long cell = s / k;
  for (int j = 0; j < k; ++j) {
    const long shift = j % 2 == 1 ? cell / 2 : 0;
    for (int i = 0; i < k; ++i) {
      if (coin(rng) == 0 || shift + (i + 1) * cell > s) continue;
      const long cx = x0 + shift + i * cell + 1, cy = y0 + j * cell + 1, cs = cell - 2;
      if (cs < 4) continue;
      // Squares fill their cell, so children fit inside; other shapes get no children.
      const int shape_kind = kind(rng);
      out.push_back(shape(shape_kind, cx, cy, cs - cs % 2, coin(rng) == 1));
      if (shape_kind == 0) subdivide(rng, cx, cy, cs, depth + 1, out);
    }
  }
}

TEST(RingNesting, MatchesTheBruteForceOnRandomFamilies) {
  for (unsigned seed = 1; seed <= 60; ++seed) {
    std::mt19937 rng(seed);
    std::vector<Ring> rings;
    subdivide(rng, 0, 0, 4096, 0, rings);
    // A second family on the same lattice to the right: shared x-coordinates across families.
    subdivide(rng, 4100, 0, 4096, 0, rings);
    if (rings.empty()) continue;
    std::vector<std::vector<detail::FilteredPoint>> pts;
    for (const Ring& r : rings) {
      pts.emplace_back();
      for (const auto& v : r) pts.back().push_back(detail::filtered(v));
    }
    ASSERT_EQ(detail::ring_parents(pts), brute_parents(rings)) << "seed " << seed;
  }
}

PolygonSet square_set(long x, long y, long s) { return {{{shape(0, x, y, s, false), {}}}}; }

std::string message(const PolygonSet& q) {
  try {
    validate_region(q);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(RingNesting, ValidationAcceptsGoodNestingAndNamesBadNesting) {
  // A polygon with two holes, one holding an island polygon: valid.
  PolygonSet good = square_set(0, 0, 100);
  good.polygons[0].holes.push_back(shape(0, 10, 10, 40, true));
  good.polygons[0].holes.push_back(shape(1, 60, 60, 30, true));
  good.polygons.push_back({shape(0, 20, 20, 10, false), {}});
  EXPECT_EQ(message(good), "");
  // The island outside every hole overlaps the polygon.
  PolygonSet overlap = good;
  overlap.polygons[1].outer = shape(0, 55, 10, 4, false);
  EXPECT_NE(message(overlap).find("overlaps polygon 0"), std::string::npos) << message(overlap);
  // A hole inside another hole of the same polygon.
  PolygonSet holes = good;
  holes.polygons[0].holes.push_back(shape(0, 12, 12, 4, true));
  EXPECT_NE(message(holes).find("holes overlap"), std::string::npos) << message(holes);
  // A hole outside its outer ring.
  PolygonSet stray = square_set(0, 0, 100);
  stray.polygons[0].holes.push_back(shape(0, 200, 0, 10, true));
  EXPECT_NE(message(stray).find("outside its outer ring"), std::string::npos) << message(stray);
  // A hole of polygon 0 lying in polygon 1, itself inside a hole of polygon 0: its container
  // is polygon 1's outer ring, not its own.
  PolygonSet deep = square_set(0, 0, 100);
  deep.polygons[0].holes.push_back(shape(0, 10, 10, 60, true));
  deep.polygons.push_back({shape(0, 20, 20, 40, false), {}});
  deep.polygons[0].holes.push_back(shape(0, 30, 30, 5, true));
  EXPECT_NE(message(deep), "");
}

} // namespace
} // namespace penshape
