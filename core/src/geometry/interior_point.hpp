#pragma once
// A point strictly inside a polygonal region, exactly: on a horizontal line through no vertex,
// the midpoint of the widest interval the region cuts from it, in its largest polygon. Internal.
#include <optional>

#include "penshape/core/polygon_set.hpp"

namespace penshape::detail {

// nullopt for an empty set (or one without area).
std::optional<ExactPoint> interior_point(const PolygonSet& set);

} // namespace penshape::detail
