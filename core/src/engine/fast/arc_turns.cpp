// ArcTurns (arc_turns.hpp): the sign of u x w for double directions, by intervals and exactly.
#include "arc_turns.hpp"

#include <CGAL/Interval_nt.h>

#include "certified.hpp"
#include "geometry/exact_predicates.hpp"

namespace penshape::fast {

ArcTurns::ArcTurns(DPt u0, DPt u1, DPt from, bool from_is_end, DPt to, bool to_is_end) {
  // `to` inside the cone (u0 -> to and to -> u1 counterclockwise), then from -> to in order;
  // `from` was `to` of the previous chord, so its cone turns are checked there.
  if (!to_is_end) {
    turns_[n_++] = {u0, to};
    turns_[n_++] = {to, u1};
  }
  if (!(from_is_end && to_is_end)) turns_[n_++] = {from, to};
}

void ArcTurns::sign_by_intervals() {
  using I = detail::IntervalNT;
  for (std::size_t k = 0; k < n_; ++k) {
    const Turn& t = turns_[k];
    const I c = I(t.u.x) * I(t.w.y) - I(t.u.y) * I(t.w.x);
    sign_[k] = c.inf() > 0 ? 1 : (c.sup() < 0 ? -1 : 0);
  }
}

bool ArcTurns::counterclockwise() const {
  for (std::size_t k = 0; k < n_; ++k) {
    if (sign_[k] > 0) continue;
    if (sign_[k] < 0) return false;
    // Products of doubles are exact as rationals.
    const Turn& t = turns_[k];
    if (cmp(Rational(t.u.x) * Rational(t.w.y), Rational(t.u.y) * Rational(t.w.x)) < 0) {
      return false;
    }
  }
  return true;
}

} // namespace penshape::fast
