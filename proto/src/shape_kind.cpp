// ShapeClass <-> v1::ShapeKind (shape_kind.hpp), one table read both ways.
#include "penshape/proto/shape_kind.hpp"

#include "penshape/types/lookup_table.hpp"

namespace penshape::proto {
namespace {

constexpr LookupTable<ShapeClass, v1::ShapeKind, 16> kShapeKinds{{
    {ShapeClass::kFreeform, v1::SHAPE_KIND_NONE},
    {ShapeClass::kSegment, v1::SHAPE_KIND_SEGMENT},
    {ShapeClass::kPolyline, v1::SHAPE_KIND_POLYLINE},
    {ShapeClass::kTriangle, v1::SHAPE_KIND_TRIANGLE},
    {ShapeClass::kQuadrilateral, v1::SHAPE_KIND_QUADRILATERAL},
    {ShapeClass::kRectangle, v1::SHAPE_KIND_RECTANGLE},
    {ShapeClass::kSquare, v1::SHAPE_KIND_SQUARE},
    {ShapeClass::kDiamond, v1::SHAPE_KIND_DIAMOND},
    {ShapeClass::kRegularPolygon, v1::SHAPE_KIND_REGULAR_POLYGON},
    {ShapeClass::kCircle, v1::SHAPE_KIND_CIRCLE},
    {ShapeClass::kEllipse, v1::SHAPE_KIND_ELLIPSE},
    {ShapeClass::kArc, v1::SHAPE_KIND_ARC},
    {ShapeClass::kArrow, v1::SHAPE_KIND_ARROW},
    {ShapeClass::kDoubleArrow, v1::SHAPE_KIND_DOUBLE_ARROW},
    {ShapeClass::kDot, v1::SHAPE_KIND_DOT},
    {ShapeClass::kPolygon, v1::SHAPE_KIND_POLYGON},
}};

} // namespace

v1::ShapeKind to_proto(ShapeClass shape) {
  return lookup_or(kShapeKinds, shape, v1::SHAPE_KIND_UNSPECIFIED);
}

std::optional<ShapeClass> from_proto(v1::ShapeKind kind) {
  return reverse_lookup(kShapeKinds, kind);
}

} // namespace penshape::proto
