// Public exact offsets and insets: validation, then the exact region operations.
#include "penshape/core/offset.hpp"

#include "geometry/exact_predicates.hpp"
#include "geometry/exact_region.hpp"

namespace penshape {
namespace {

void check_convex_kernel(const Ring& k) {
  const std::size_t n = k.size();
  if (n < 3) throw InvalidInput("the convex summand needs at least 3 vertices");
  const ExactPoint origin{0, 0};
  const auto o = detail::filtered(origin);
  for (std::size_t i = 0; i < n; ++i) {
    const auto a = detail::filtered(k[i]);
    const auto b = detail::filtered(k[(i + 1) % n]);
    const auto c = detail::filtered(k[(i + 2) % n]);
    if (detail::orientation(a, b, c) <= 0) {
      throw InvalidInput(
          "the convex summand is not strictly convex and counterclockwise at vertex " +
          std::to_string((i + 1) % n));
    }
    if (detail::orientation(a, b, o) < 0) {
      throw InvalidInput("the convex summand does not contain the origin (edge " +
                         std::to_string(i) + ")");
    }
  }
}

detail::ExactRegion prepared(const PolygonSet& x) {
  validate_region(x);
  PolygonSet oriented = x;
  normalize_orientation(oriented);
  return detail::ExactRegion::from(oriented);
}

} // namespace

PolygonSet offset_by(const PolygonSet& x, const Ring& k, const CancelHook& cancel) {
  check_convex_kernel(k);
  return prepared(x).minkowski_sum(k, cancel).to_polygon_set();
}

PolygonSet inset_by(const PolygonSet& x, const Ring& k, const CancelHook& cancel) {
  check_convex_kernel(k);
  return prepared(x).inset(k, cancel).to_polygon_set();
}

bool region_contains(const PolygonSet& outer, const PolygonSet& inner) {
  return prepared(outer).contains(prepared(inner));
}

} // namespace penshape
