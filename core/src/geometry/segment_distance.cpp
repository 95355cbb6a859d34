#include "segment_distance.hpp"

#include "distance_kernel.hpp"

namespace penshape::detail {

Rational squared_distance_to_segment(const ExactPoint& p, const ExactPoint& s,
                                     const ExactPoint& t) {
  // The rational instance of the one kernel: it always decides (rationals are ordered).
  return *squared_distance_to_segment<Rational>({p.x, p.y}, {s.x, s.y}, {t.x, t.y});
}

int orientation(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  return sgn((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

namespace {
bool on_segment(const ExactPoint& a, const ExactPoint& b, const ExactPoint& p) {
  return orientation(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}
} // namespace

bool segments_meet(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c,
                   const ExactPoint& d) {
  const int o1 = orientation(a, b, c);
  const int o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a);
  const int o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

bool strictly_inside_ring(const ExactPoint& p, const Ring& ring) {
  bool inside = false;
  const std::size_t n = ring.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const ExactPoint& a = ring[i];
    const ExactPoint& b = ring[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      // x-coordinate of the edge at height p.y compared with p.x, without division.
      const Rational lhs = (p.x - a.x) * (b.y - a.y);
      const Rational rhs = (b.x - a.x) * (p.y - a.y);
      if ((b.y > a.y) ? lhs < rhs : lhs > rhs) inside = !inside;
    }
  }
  return inside;
}

} // namespace penshape::detail
