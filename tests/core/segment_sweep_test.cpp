// The Shamos–Hoey contact sweep (core/src/geometry/segment_sweep) against a brute-force check of
// every pair written here in plain rational arithmetic: random rings on a coarse grid (so
// touching vertices, collinear overlaps and vertical edges are common), the same rings moved
// by 1e-30 (near-degenerate: doubles cannot tell, exact arithmetic must), star polygons of a
// few hundred edges with and without a planted contact, and soups of free segments. The ring
// form (`find_ring_contact`, one event per vertex) on the same kinds of rings, and on rings
// with repeated vertices (zero-length edges, one- and two-vertex rings), against both.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory_resource>
#include <random>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "geometry/node_recycler.hpp"
#include "geometry/segment_sweep.hpp"

namespace penshape {
namespace {

using Pt = ExactPoint;

int sign_of(const Rational& v) { return sgn(v) > 0 ? 1 : (sgn(v) < 0 ? -1 : 0); }

int turn(const Pt& o, const Pt& a, const Pt& b) {
  return sign_of((a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x));
}

bool within(const Pt& a, const Pt& b, const Pt& c) { // c in the box of ab
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

bool closed_meet(const Pt& a, const Pt& b, const Pt& c, const Pt& d) {
  const int o1 = turn(a, b, c), o2 = turn(a, b, d), o3 = turn(c, d, a), o4 = turn(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && within(a, b, c)) || (o2 == 0 && within(a, b, d)) ||
         (o3 == 0 && within(c, d, a)) || (o4 == 0 && within(c, d, b));
}

struct Soup {
  std::vector<std::pair<Pt, Pt>> segments;
  std::set<std::pair<std::size_t, std::size_t>> neighbours; // may share their common end

  bool adjacent(std::size_t i, std::size_t j) const {
    return neighbours.count({std::min(i, j), std::max(i, j)}) != 0;
  }

  // The pair is forbidden: neighbours meeting beyond one common endpoint, or others meeting.
  bool forbidden(std::size_t i, std::size_t j) const {
    const auto& [a, b] = segments[i];
    const auto& [c, d] = segments[j];
    if (adjacent(i, j)) {
      for (const auto& [shared, p, q] :
           {std::tuple{a, b, c == a ? d : c}, std::tuple{b, a, c == b ? d : c}}) {
        if (!(shared == c || shared == d)) continue;
        return turn(shared, p, q) == 0 && (within(shared, p, q) || within(shared, q, p));
      }
    }
    return closed_meet(a, b, c, d);
  }

  bool brute_force() const {
    for (std::size_t i = 0; i < segments.size(); ++i) {
      for (std::size_t j = i + 1; j < segments.size(); ++j) {
        if (forbidden(i, j)) return true;
      }
    }
    return false;
  }

  void add_ring(const std::vector<Pt>& ring) {
    const std::size_t first = segments.size();
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      segments.push_back({ring[i], ring[(i + 1) % n]});
      const std::size_t next = first + (i + 1) % n;
      neighbours.insert({std::min(first + i, next), std::max(first + i, next)});
    }
  }
};

// Runs the sweep; checks its verdict against brute force, and that any pair it names is one.
void expect_agrees(const Soup& soup, const std::string& what) {
  std::vector<detail::SweepSegment> segs;
  for (const auto& [a, b] : soup.segments)
    segs.push_back({detail::filtered(a), detail::filtered(b)});
  const auto found = detail::find_forbidden_contact(
      segs, [&](std::size_t i, std::size_t j) { return soup.adjacent(i, j); });
  ASSERT_EQ(found.has_value(), soup.brute_force()) << what;
  if (found) {
    EXPECT_TRUE(soup.forbidden(found->first, found->second)) << what;
  }
}

Pt grid_point(std::mt19937& rng, int size, const Rational& nudge) {
  std::uniform_int_distribution<int> coord(0, size);
  std::uniform_int_distribution<int> sign(-1, 1);
  return {Rational(coord(rng)) + nudge * sign(rng), Rational(coord(rng)) + nudge * sign(rng)};
}

// Rings without zero-length edges (the validator rejects those before the sweep).
std::vector<Pt> random_ring(std::mt19937& rng, int grid, const Rational& nudge) {
  std::uniform_int_distribution<int> size(3, 8);
  std::vector<Pt> ring;
  const int n = size(rng);
  while (static_cast<int>(ring.size()) < n) {
    const Pt p = grid_point(rng, grid, nudge);
    if (ring.empty() || !(ring.back() == p)) ring.push_back(p);
  }
  if (ring.front() == ring.back()) ring.pop_back();
  return ring;
}

TEST(SegmentSweep, AgreesWithBruteForceOnRandomRings) {
  std::mt19937 rng(7);
  int clean = 0, contact = 0;
  for (int t = 0; t < 3000; ++t) {
    Soup soup;
    const int rings = 1 + t % 3;
    for (int k = 0; k < rings; ++k) {
      const auto ring = random_ring(rng, 6, Rational(0));
      if (ring.size() >= 3) soup.add_ring(ring);
    }
    expect_agrees(soup, "trial " + std::to_string(t));
    (soup.brute_force() ? contact : clean) += 1;
  }
  EXPECT_GT(clean, 100); // both verdicts are exercised
  EXPECT_GT(contact, 100);
}

TEST(SegmentSweep, AgreesWithBruteForceOnNearDegenerateRings) {
  // Vertices moved by ±1e-30: touching becomes missing by 1e-30 or crossing by it.
  std::mt19937 rng(11);
  const Rational nudge = Rational(1) / Rational(mpz_class("1000000000000000000000000000000"));
  int clean = 0, contact = 0;
  for (int t = 0; t < 2000; ++t) {
    Soup soup;
    for (int k = 0; k < 1 + t % 2; ++k) {
      const auto ring = random_ring(rng, 4, nudge);
      if (ring.size() >= 3) soup.add_ring(ring);
    }
    expect_agrees(soup, "trial " + std::to_string(t));
    (soup.brute_force() ? contact : clean) += 1;
  }
  EXPECT_GT(clean, 50);
  EXPECT_GT(contact, 50);
}

TEST(SegmentSweep, AgreesWithBruteForceOnFreeSegments) {
  std::mt19937 rng(5);
  for (int t = 0; t < 2000; ++t) {
    Soup soup;
    const int n = 2 + t % 5;
    while (static_cast<int>(soup.segments.size()) < n) {
      const Pt a = grid_point(rng, 8, Rational(0));
      const Pt b = grid_point(rng, 8, Rational(0));
      if (!(a == b)) soup.segments.push_back({a, b});
    }
    expect_agrees(soup, "trial " + std::to_string(t));
  }
}

// A star of about n vertices at random radii 20-60, rounded to integers (repeats dropped).
std::vector<Pt> star_ring(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> radius(20.0, 60.0);
  std::vector<Pt> ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.141592653589793 * i / n;
    const double r = radius(rng);
    const Pt p{Rational(static_cast<long>(std::lround(r * std::cos(a)))),
               Rational(static_cast<long>(std::lround(r * std::sin(a))))};
    if (ring.empty() || !(ring.back() == p)) ring.push_back(p);
  }
  if (ring.front() == ring.back()) ring.pop_back();
  return ring;
}

// Star polygons of 60-300 vertices on a coarse grid: rounding makes some of them touch
// themselves; others get one vertex moved onto a non-neighbouring edge's endpoint.
TEST(SegmentSweep, AgreesWithBruteForceOnLargeStars) {
  std::mt19937 rng(3);
  int clean = 0, contact = 0;
  for (int t = 0; t < 60; ++t) {
    std::vector<Pt> ring = star_ring(rng, 60 + 4 * t);
    if (t % 3 == 0) ring[ring.size() / 2] = ring[ring.size() / 2 + 7]; // a planted contact
    Soup soup;
    soup.add_ring(ring);
    expect_agrees(soup, "star " + std::to_string(t));
    (soup.brute_force() ? contact : clean) += 1;
  }
  EXPECT_GT(clean, 5);
  EXPECT_GT(contact, 5);
}

// The ring form on the same rings: its verdict against brute force and against the segment
// form, and the edges it names (ring, index) are a forbidden pair, the first one first.
// Returns brute force's verdict.
bool expect_ring_form_agrees(const std::vector<std::vector<Pt>>& rings, const std::string& what) {
  Soup soup;
  std::vector<std::size_t> first_edge;
  std::vector<std::vector<detail::FilteredPoint>> points;
  for (const auto& ring : rings) {
    first_edge.push_back(soup.segments.size());
    soup.add_ring(ring);
    points.emplace_back();
    for (const Pt& p : ring) points.back().push_back(detail::filtered(p));
  }
  const std::vector<std::span<const detail::FilteredPoint>> spans(points.begin(), points.end());
  const auto found = detail::find_ring_contact(spans);
  const bool expected = soup.brute_force();
  EXPECT_EQ(found.has_value(), expected) << what;
  std::vector<detail::SweepSegment> segs;
  for (const auto& [a, b] : soup.segments) {
    segs.push_back({detail::filtered(a), detail::filtered(b)});
  }
  const auto by_segments = detail::find_forbidden_contact(
      segs, [&](std::size_t i, std::size_t j) { return soup.adjacent(i, j); });
  EXPECT_EQ(by_segments.has_value(), expected) << what;
  if (found) {
    const std::size_t i = first_edge[found->first.ring] + found->first.index;
    const std::size_t j = first_edge[found->second.ring] + found->second.index;
    EXPECT_LT(i, j) << what;
    EXPECT_TRUE(soup.forbidden(i, j)) << what;
  }
  return expected;
}

// Any vertices at all, repeats included (consecutive ones make zero-length edges).
std::vector<Pt> ring_with_repeats(std::mt19937& rng, int grid, const Rational& nudge) {
  std::uniform_int_distribution<int> size(1, 7);
  const int n = size(rng);
  std::vector<Pt> ring;
  ring.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) ring.push_back(grid_point(rng, grid, nudge));
  return ring;
}

TEST(SegmentSweep, RingFormAgreesWithBruteForceOnRandomRings) {
  std::mt19937 rng(17);
  int clean = 0, contact = 0;
  for (int t = 0; t < 3000; ++t) {
    std::vector<std::vector<Pt>> rings;
    for (int k = 0; k < 1 + t % 4; ++k) {
      auto ring = random_ring(rng, 6 + t % 3, Rational(0));
      if (ring.size() >= 3) rings.push_back(std::move(ring));
    }
    (expect_ring_form_agrees(rings, "trial " + std::to_string(t)) ? contact : clean) += 1;
  }
  EXPECT_GT(clean, 100); // both verdicts are exercised
  EXPECT_GT(contact, 100);
}

TEST(SegmentSweep, RingFormAgreesWithBruteForceOnNearDegenerateRings) {
  std::mt19937 rng(19);
  const Rational nudge = Rational(1) / Rational(mpz_class("1000000000000000000000000000000"));
  for (int t = 0; t < 2000; ++t) {
    std::vector<std::vector<Pt>> rings;
    for (int k = 0; k < 1 + t % 2; ++k) {
      auto ring = random_ring(rng, 4, nudge);
      if (ring.size() >= 3) rings.push_back(std::move(ring));
    }
    expect_ring_form_agrees(rings, "trial " + std::to_string(t));
  }
}

// Repeated vertices, consecutive or not: the fast engine's rounded rings may have them (a ring
// may even round to one or two points).
TEST(SegmentSweep, RingFormAgreesWithBruteForceOnRepeatedVertices) {
  std::mt19937 rng(23);
  for (int t = 0; t < 3000; ++t) {
    std::vector<std::vector<Pt>> rings(static_cast<std::size_t>(1 + t % 3));
    for (auto& ring : rings) ring = ring_with_repeats(rng, 3, Rational(0));
    expect_ring_form_agrees(rings, "trial " + std::to_string(t));
  }
}

// Large star rings, with and without a planted contact, beside a small ring: vertices of the
// star's many edges meet at one event point and the status is long.
TEST(SegmentSweep, RingFormAgreesWithBruteForceOnLargeStars) {
  std::mt19937 rng(29);
  for (int t = 0; t < 40; ++t) {
    std::vector<Pt> ring = star_ring(rng, 80 + 5 * t);
    if (t % 3 == 0) ring[ring.size() / 3] = ring[ring.size() / 3 + 5]; // a planted contact
    const std::vector<Pt> square{{Rational(70), Rational(0)},
                                 {Rational(72), Rational(0)},
                                 {Rational(72), Rational(2)},
                                 {Rational(70), Rational(2)}};
    expect_ring_form_agrees({square, ring}, "star " + std::to_string(t));
  }
}

// The sweep's node recycler (geometry/node_recycler.hpp): a freed block comes back for the next
// node, live blocks never overlap and keep their contents while others come and go, and a
// std::pmr::set on it holds what std::set holds after random inserts and erases.
TEST(NodeRecycler, RecyclesFreedNodesAndKeepsLiveOnesApart) {
  detail::NodeRecycler pool;
  constexpr std::size_t kSize = 40;
  void* first = pool.allocate(kSize, 8);
  pool.deallocate(first, kSize, 8);
  EXPECT_EQ(pool.allocate(kSize, 8), first);

  std::mt19937 rng(27);
  std::vector<unsigned char*> live{static_cast<unsigned char*>(first)};
  std::vector<unsigned char> tag{0};
  std::fill_n(live[0], kSize, tag[0]);
  for (int step = 0; step < 20000; ++step) {
    if (live.size() > 1 && rng() % 3 == 0) {
      const std::size_t k = rng() % live.size();
      pool.deallocate(live[k], kSize, 8);
      live.erase(live.begin() + static_cast<std::ptrdiff_t>(k));
      tag.erase(tag.begin() + static_cast<std::ptrdiff_t>(k));
    } else {
      auto* p = static_cast<unsigned char*>(pool.allocate(kSize, 8));
      const auto t = static_cast<unsigned char>(rng());
      std::fill_n(p, kSize, t);
      live.push_back(p);
      tag.push_back(t);
    }
  }
  for (std::size_t k = 0; k < live.size(); ++k) {
    ASSERT_TRUE(std::all_of(live[k], live[k] + kSize, [&](unsigned char c) { return c == tag[k]; }))
        << "block " << k << " overwritten";
  }
  std::vector<unsigned char*> sorted = live;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 1; k < sorted.size(); ++k) {
    ASSERT_GE(sorted[k] - sorted[k - 1], static_cast<std::ptrdiff_t>(kSize)) << "blocks overlap";
  }

  detail::NodeRecycler set_pool;
  std::pmr::set<int> recycled(&set_pool);
  std::set<int> plain;
  for (int step = 0; step < 50000; ++step) {
    const int v = static_cast<int>(rng() % 500);
    if (rng() % 2 == 0) {
      recycled.insert(v);
      plain.insert(v);
    } else {
      recycled.erase(v);
      plain.erase(v);
    }
  }
  EXPECT_TRUE(std::equal(recycled.begin(), recycled.end(), plain.begin(), plain.end()));
}

} // namespace
} // namespace penshape
