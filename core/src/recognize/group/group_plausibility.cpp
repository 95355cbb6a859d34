// Drawn-in-pieces rules for unions of several strokes (group_plausibility.hpp).
#include "recognize/group/group_plausibility.hpp"

#include <algorithm>
#include <vector>

#include "recognize/group/group_classifier.hpp"
#include "recognize/group/stroke_chain.hpp"

namespace penshape::recognize_detail {
namespace {

bool is_round(ShapeClass c) {
  return c == ShapeClass::kCircle || c == ShapeClass::kEllipse || c == ShapeClass::kArc;
}

bool closed_round(ShapeClass c) { return c == ShapeClass::kCircle || c == ShapeClass::kEllipse; }

bool straight(ShapeClass c) { return c == ShapeClass::kSegment || c == ShapeClass::kPolyline; }

// Why a piece recognized alone as `own` is no piece of a `group` (empty when it may be one).
std::string kind_mismatch(ShapeClass group, ShapeClass own) {
  if (is_round(group) && straight(own))
    return "a round shape has a straight stroke among its pieces";
  // Not an arc: a side and a rounded corner drawn alone often read as one.
  if (!is_round(group) && closed_round(own)) {
    return "a straight-sided shape has a circle or ellipse among its pieces";
  }
  return {};
}

} // namespace

std::string group_implausibility(const Recognition& r, std::span<const StrokeInput> strokes,
                                 const RecognizerConfig& config) {
  if (strokes.size() < 2) return {};
  // An arrow's head meets its shaft at the head's middle (its tip), not at an end.
  if (r.shape == ShapeClass::kArrow || r.shape == ShapeClass::kDoubleArrow) return {};
  std::vector<std::vector<PointD>> paths;
  double stroke_epsilon = 0.0;
  for (const StrokeInput& s : strokes) {
    paths.push_back(distinct_path(s.samples));
    // The tolerance of the stroke alone: a gap between pieces is measured against the pieces
    // drawn, not against the whole group, whose epsilon grows with every piece added.
    stroke_epsilon = std::max(stroke_epsilon, choose_tolerance(s.samples, config).epsilon);
  }
  const double join = 2.0 * r.pen_radius + stroke_epsilon;
  for (const double jump : chain_jumps(paths)) {
    if (jump > join) {
      return "the strokes do not chain end to end (a jump between pieces is wider than 2 r + "
             "the epsilon of a piece)";
    }
  }
  // Each piece is a piece of the shape's own kind: a D or a P (a bar and a bowl) is no ellipse,
  // a circle crossed by a bar no polygon, whatever band covers the union.
  for (const StrokeInput& s : strokes) {
    std::string why = kind_mismatch(r.shape, recognize(s.samples, config).shape);
    if (!why.empty()) return why;
  }
  return {};
}

} // namespace penshape::recognize_detail
