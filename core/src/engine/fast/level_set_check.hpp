#pragma once
// The one primitive both YES inclusions reduce to (README.md, "Why YES is certified"):
//
//   every point z with d(z, A) = level satisfies d(z, ∂B) > clearance and z outside B,
//
// for integer regions A and B given by simple rings with the region on their left. The level
// set {d(·, A) = level} lies on the outward offset segments of A's edges and on the arcs around
// A's convex vertices; we walk those curves (arcs as chords within a known sagitta), remove the
// parts that are provably closer than `level` to another edge of A (so not on the level set),
// and check the rest against B with segment-to-segment distance lower bounds and one exact
// winding number per remaining piece. Every deciding comparison is certified (certified.hpp)
// and the chords' errors are derived with outward rounding: false means "not verified".
#include <cstdint>
#include <vector>

#include "penshape/core/deconstruct.hpp"
#include "segment_index.hpp"

namespace penshape::fast {

// An axis-parallel box of the grid plane.
struct Window {
  double lo_x, lo_y, hi_x, hi_y;
};

// What walks of one region A at one level and sagitta prove about A alone, for the next walk of
// the same (A, level, max_sagitta) against another B: for each top-level piece (the offset
// segment of each edge, the first 31 chords of the arc around each vertex), whether the deep
// test (every point of the piece's curve closer than `level` to an edge of A) held. That test
// depends on A, the level and the piece only, and a piece is the same in every such walk, so a
// remembered result is the result the test would give again (a split chord is not remembered).
// The solution simplifier checks many candidates P against one A: most pieces of a jagged A are
// deep, and each later walk only checks the others against P.
class LevelSetMemo {
 public:
  LevelSetMemo(const SegmentIndex& a, double level, double max_sagitta)
      : a_(&a),
        level_(level),
        max_sagitta_(max_sagitta),
        known_(a.segments().size()),
        deep_(a.segments().size()) {}

  // Whether this memo is for walks of A at this level and sagitta.
  [[nodiscard]] bool serves(const SegmentIndex* a, double level, double max_sagitta) const {
    return a == a_ && level == level_ && max_sagitta == max_sagitta_;
  }
  // Entry `bit` of vertex `v`: 0 the edge leaving v, 1 + k the k-th chord of v's arc.
  static constexpr unsigned kEntries = 32;
  [[nodiscard]] bool known(std::size_t v, unsigned bit) const { return (known_[v] >> bit) & 1U; }
  [[nodiscard]] bool deep(std::size_t v, unsigned bit) const { return (deep_[v] >> bit) & 1U; }
  void record(std::size_t v, unsigned bit, bool deep) {
    known_[v] |= 1U << bit;
    if (deep) deep_[v] |= 1U << bit;
  }

 private:
  const SegmentIndex* a_;
  double level_;
  double max_sagitta_;
  std::vector<std::uint32_t> known_, deep_; // per vertex of A, in the order of its rings
};

struct LevelSetQuery {
  const SegmentIndex* a = nullptr; // region whose level set is walked
  double level = 0.0;              // grid units, > 1, taken as exact
  const SegmentIndex* b = nullptr; // region the level set must stay away from
  double clearance = 0.0;          // grid units, >= 3/4 (> the rounding of a point to the grid)
  double max_sagitta = 1.0;        // arcs: first chords of 4x this sagitta, halved where they fail
  // When set, only the level set's points inside this box are checked: pieces of the walk
  // whose every point is proven outside it (with two units to spare for the doubles' rounding
  // of the box comparisons, whose coordinates are below 2^32) are skipped. The caller proves
  // the points outside some other way (yes_certificate.cpp: a local change of B).
  const Window* window = nullptr;
  // When set and serving (a, level, max_sagitta): deep tests are taken from it and recorded.
  LevelSetMemo* memo = nullptr;
  // Whether each piece is first tested clear of B, then deep (the same answer in either order,
  // level_set_check.cpp). Worth it when the clearance is small, so the clear test meets few
  // edges of B, and A has few edges near its own level set (the deep test then mostly fails):
  // (B1), whose A is P and B is Q̃ at clearance 3/4 (KAZ at r = w/30: 1.9% fewer
  // instructions per decision; (A1) in this order costs 6% more). Either way, a piece that
  // starts where a piece proven clear of B ended is tested clear-first.
  bool clear_first = false;
};

bool level_set_avoids(const LevelSetQuery& query, const CancelHook& cancel);

// Whether the rings are simple and pairwise disjoint except at shared vertices of consecutive
// edges (exact integer tests; the level-set argument needs it).
bool rings_are_simple(const SegmentIndex& index);

// Whether simple, disjoint rings bound their region on the left: every counterclockwise ring
// lies where the other rings wind 0 times, every clockwise ring where they wind once. Then the
// winding number is 1 just left of every edge and 0 just right of it.
bool rings_are_nested_consistently(const SegmentIndex& index);

// Both of the above: what the level-set walk needs of A.
inline bool is_certifiable_region(const SegmentIndex& index) {
  return rings_are_simple(index) && rings_are_nested_consistently(index);
}

} // namespace penshape::fast
