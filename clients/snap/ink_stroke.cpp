// The range check every reader applies to a stroke's points (see ink_stroke.hpp).
#include "ink_stroke.hpp"

#include <cmath>

namespace penshape::snap {

bool coordinates_in_range(const std::vector<StrokePoint>& points) {
  for (const StrokePoint& p : points) {
    if (!(std::abs(p.x) <= kMaxCoordinate) || !(std::abs(p.y) <= kMaxCoordinate)) return false;
  }
  return true;
}

} // namespace penshape::snap
