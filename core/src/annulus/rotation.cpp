// Translation and rotation: input checks and the choice of method (see rotation.hpp).
#include "penshape/core/annulus/rotation.hpp"

#include <cmath>
#include <string>

#include "point_set.hpp"
#include "rotation_internal.hpp"

namespace penshape::annulus {
namespace {

void validate_rotation(const TemplatePolygon& p, OuterOffset outer,
                       const std::vector<PointD>& points, const Limits& limits) {
  if (!p.convex() && outer == OuterOffset::kLinearized) {
    throw InvalidInput("the linearized outer offset needs a convex template");
  }
  validate_points(points, limits);
  if (points.size() > limits.max_rotation_points) {
    throw InvalidInput("rotation placement takes at most " +
                       std::to_string(limits.max_rotation_points) + " points, got " +
                       std::to_string(points.size()));
  }
}

void validate_options(const RotationOptions& o) {
  if (!(o.angle_resolution > 0.0) || !std::isfinite(o.angle_resolution) ||
      !(o.translation_resolution > 0.0) || !std::isfinite(o.translation_resolution)) {
    throw InvalidInput("rotation resolutions must be finite and positive");
  }
}

RotationMethod pick(const TemplatePolygon& p, OuterOffset outer, const RotationOptions& o) {
  if (o.method == RotationMethod::kDiagram && (!p.convex() || outer != OuterOffset::kLinearized)) {
    throw InvalidInput("rotation diagrams need a convex template and the linearized outer offset");
  }
  if (o.method != RotationMethod::kAuto) return o.method;
  return outer == OuterOffset::kLinearized ? RotationMethod::kDiagram : RotationMethod::kCellSearch;
}

} // namespace

MaxCoverResult max_cover_rotation(const TemplatePolygon& p, OuterOffset outer, double delta,
                                  const std::vector<PointD>& points, const RotationOptions& options,
                                  const Limits& limits) {
  validate_rotation(p, outer, points, limits);
  validate_delta(delta, limits);
  validate_options(options);
  RotationMethod m = pick(p, outer, options);
  if (m == RotationMethod::kDiagram && options.method == RotationMethod::kAuto) {
    const auto n = static_cast<double>(detail::merge_duplicates(points).points.size());
    const auto vertices = static_cast<double>(p.size());
    if (n * n * n * vertices * vertices > options.diagram_max_work) {
      m = RotationMethod::kCellSearch; // the diagram sweep is cubic in n
    }
  }
  switch (m) {
    case RotationMethod::kDiagram:
      return detail::max_cover_rotation_diagram(p, delta, points);
    case RotationMethod::kAngleSearch:
      return detail::max_cover_rotation_angles(p, outer, delta, points, options);
    default:
      return detail::max_cover_rotation_cells(p, outer, delta, points, options);
  }
}

DecisionResult decide_rotation(const TemplatePolygon& p, OuterOffset outer, double delta,
                               const std::vector<PointD>& points, const RotationOptions& options,
                               const Limits& limits) {
  validate_rotation(p, outer, points, limits);
  validate_delta(delta, limits);
  validate_options(options);
  switch (pick(p, outer, options)) {
    case RotationMethod::kDiagram:
      return detail::decide_rotation_diagram(p, delta, points);
    case RotationMethod::kAngleSearch:
      return detail::decide_rotation_angles(p, outer, delta, points, options);
    default:
      return detail::decide_rotation_cells(p, outer, delta, points, options);
  }
}

MinWidthResult min_width_rotation(const TemplatePolygon& p, OuterOffset outer,
                                  const std::vector<PointD>& points, const MinWidthOptions& options,
                                  const RotationOptions& rotation, const Limits& limits) {
  validate_rotation(p, outer, points, limits);
  validate_options(rotation);
  switch (pick(p, outer, rotation)) {
    case RotationMethod::kDiagram:
      return detail::min_width_rotation_diagram(p, points, options);
    case RotationMethod::kAngleSearch:
      return detail::min_width_rotation_angles(p, outer, points, options, rotation);
    default:
      return detail::min_width_rotation_cells(p, outer, points, options, rotation);
  }
}

} // namespace penshape::annulus
