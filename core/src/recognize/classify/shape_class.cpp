// Names of the shape classes (CLI, JSON, labels), and which classes are convex polygons.
#include <array>
#include <utility>

#include "penshape/core/recognize.hpp"
#include "recognize/classify/classifier.hpp"

namespace penshape {
namespace {
constexpr std::array<std::pair<ShapeClass, const char*>, 16> kNames{{
    {ShapeClass::kFreeform, "freeform"},
    {ShapeClass::kSegment, "segment"},
    {ShapeClass::kPolyline, "polyline"},
    {ShapeClass::kTriangle, "triangle"},
    {ShapeClass::kQuadrilateral, "quadrilateral"},
    {ShapeClass::kRectangle, "rectangle"},
    {ShapeClass::kSquare, "square"},
    {ShapeClass::kDiamond, "diamond"},
    {ShapeClass::kRegularPolygon, "regular_polygon"},
    {ShapeClass::kCircle, "circle"},
    {ShapeClass::kEllipse, "ellipse"},
    {ShapeClass::kArc, "arc"},
    {ShapeClass::kArrow, "arrow"},
    {ShapeClass::kDoubleArrow, "double_arrow"},
    {ShapeClass::kDot, "dot"},
    {ShapeClass::kPolygon, "polygon"},
}};
} // namespace

const char* to_string(ShapeClass c) {
  for (const auto& [k, name] : kNames) {
    if (k == c) return name;
  }
  return "freeform";
}

std::optional<ShapeClass> shape_class_from_string(const std::string& name) {
  for (const auto& [k, n] : kNames) {
    if (name == n) return k;
  }
  return std::nullopt;
}

} // namespace penshape

namespace penshape::recognize_detail {

bool convex_polygon(ShapeClass c) {
  switch (c) {
    case ShapeClass::kTriangle:
    case ShapeClass::kQuadrilateral:
    case ShapeClass::kRectangle:
    case ShapeClass::kSquare:
    case ShapeClass::kDiamond:
    case ShapeClass::kRegularPolygon:
      return true;
    default:
      return false;
  }
}

} // namespace penshape::recognize_detail
