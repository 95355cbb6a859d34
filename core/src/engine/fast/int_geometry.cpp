#include "int_geometry.hpp"

#include <algorithm>

namespace penshape::fast {
namespace {

// Sign of the orientation of c relative to a->b in double, or 0 when rounding could flip it.
int robust_side(DPt a, DPt b, DPt c) {
  const double ux = b.x - a.x;
  const double uy = b.y - a.y;
  const double vx = c.x - a.x;
  const double vy = c.y - a.y;
  const double cross = ux * vy - uy * vx;
  // Error of the products and the subtraction: a few ulps of the operand magnitudes.
  const double bound = 1e-12 * (std::fabs(ux * vy) + std::fabs(uy * vx)) + 1e-9;
  if (cross > bound) return 1;
  if (cross < -bound) return -1;
  return 0;
}

} // namespace

double segment_segment_distance_lower(DPt p, DPt q, DPt a, DPt b) {
  const int s1 = robust_side(a, b, p);
  const int s2 = robust_side(a, b, q);
  const int s3 = robust_side(p, q, a);
  const int s4 = robust_side(p, q, b);
  // Unless both pairs are strictly separated, the segments may touch or cross.
  if (!(s1 * s2 > 0 || s3 * s4 > 0)) return 0.0;
  return std::min({point_segment_distance(p, a, b), point_segment_distance(q, a, b),
                   point_segment_distance(a, p, q), point_segment_distance(b, p, q)});
}

Int128 twice_area(const IRing& ring) {
  Int128 sum = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const IPt& a = ring[i];
    const IPt& b = ring[(i + 1) % n];
    sum += static_cast<Int128>(a.x) * b.y - static_cast<Int128>(b.x) * a.y;
  }
  return sum;
}

int winding_number(const IRings& rings, IPt p) {
  int w = 0;
  for (const IRing& ring : rings) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const IPt& a = ring[i];
      const IPt& b = ring[(i + 1) % n];
      if (a.y <= p.y) {
        if (b.y > p.y && orientation(a, b, p) > 0) ++w;
      } else if (b.y <= p.y && orientation(a, b, p) < 0) {
        --w;
      }
    }
  }
  return w;
}

void clean_rings(IRings& rings) {
  for (IRing& ring : rings) {
    IRing out;
    out.reserve(ring.size());
    for (const IPt& p : ring) {
      if (out.empty() || !(out.back() == p)) out.push_back(p);
    }
    while (out.size() > 1 && out.front() == out.back()) out.pop_back();
    ring = std::move(out);
  }
  std::erase_if(rings, [](const IRing& r) { return r.size() < 3 || twice_area(r) == 0; });
}

} // namespace penshape::fast
