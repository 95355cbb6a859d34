#include "int_geometry.hpp"

#include <algorithm>

#include "geometry/ring_area.hpp"

namespace penshape::fast {
Int128 twice_area(const IRing& ring) { return detail::twice_signed_area_in<Int128>(ring); }

void remove_repeats(IRings& rings) {
  for (IRing& ring : rings) {
    IRing out;
    out.reserve(ring.size());
    for (const IPt& p : ring) {
      if (out.empty() || !(out.back() == p)) out.push_back(p);
    }
    while (out.size() > 1 && out.front() == out.back()) out.pop_back();
    ring = std::move(out);
  }
}

void clean_rings(IRings& rings) {
  remove_repeats(rings);
  std::erase_if(rings, [](const IRing& r) { return r.size() < 3 || twice_area(r) == 0; });
}

} // namespace penshape::fast
