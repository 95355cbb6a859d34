#pragma once
// The turn checks of the level-set walk's arcs (level_set_check.cpp): the chords of the arc
// around a convex vertex join directions proposed by cos/sin, and they cover the arc from the end
// normal u0 to u1 only when every proposed direction lies in the cone of u0 and u1 (< pi, the
// vertex is convex) and consecutive directions turn counterclockwise. These checks decide
// whether a piece may be verified, so they are certified: interval signs under upward rounding
// first (batched with the chord's other interval work), exact rationals when those cannot tell.
#include <array>
#include <cstddef>

#include "int_geometry.hpp"

namespace penshape::fast {

class ArcTurns {
 public:
  // The chord from direction `from` to `to` of the arc from u0 to u1; an end normal (u0 or u1
  // itself, `*_is_end`) is in the cone and in order with the other by convexity: not checked.
  ArcTurns(DPt u0, DPt u1, DPt from, bool from_is_end, DPt to, bool to_is_end);

  // The interval sign of each turn. Requires upward rounding (UpwardRounding).
  void sign_by_intervals();
  // Whether no turn is clockwise (a zero turn is allowed: the chord then is a point or lies on
  // an end normal); the turns the intervals could not tell are decided exactly. Call after
  // sign_by_intervals, in any rounding mode.
  [[nodiscard]] bool counterclockwise() const;

 private:
  struct Turn {
    DPt u;
    DPt w;
  };
  std::array<Turn, 3> turns_{};
  std::array<int, 3> sign_{};
  std::size_t n_ = 0;
};

} // namespace penshape::fast
