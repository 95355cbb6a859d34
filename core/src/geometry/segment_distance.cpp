// The rational instance of the kernel's point-to-segment distance, compiled once.
#include "segment_distance.hpp"

#include "distance_kernel.hpp"

namespace penshape::detail {

Rational squared_distance_to_segment(const ExactPoint& p, const ExactPoint& s,
                                     const ExactPoint& t) {
  // The rational instance of the one kernel: it always decides (rationals are ordered).
  return *squared_distance_to_segment<Rational>({p.x, p.y}, {s.x, s.y}, {t.x, t.y});
}

} // namespace penshape::detail
