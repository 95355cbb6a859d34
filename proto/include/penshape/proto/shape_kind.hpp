#pragma once
// The one conversion between the recognizer's shape classes (core) and penshape.v1's ShapeKind,
// both ways: the daemon names the shapes it sends, `penshape snap` reads them back.
#include <optional>

#include "penshape/core/recognize.hpp"
#include "penshape/v1/shape.pb.h"

namespace penshape::proto {

[[nodiscard]] v1::ShapeKind to_proto(ShapeClass shape);
// kFreeform for SHAPE_KIND_NONE; none for SHAPE_KIND_UNSPECIFIED and kinds this build does not
// know.
[[nodiscard]] std::optional<ShapeClass> from_proto(v1::ShapeKind kind);

} // namespace penshape::proto
