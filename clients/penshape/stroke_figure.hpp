#pragma once
// penshape.v1 messages → the SVG figures of penshape_render (for `watch --svg-dir`).
#include <optional>
#include <string>

#include "penshape/render/figure.hpp"
#include "penshape/v1/live.pb.h"

namespace penshape::cli {

// The shape as an outline in mm; nullopt for SHAPE_KIND_NONE or a shape without parameters.
std::optional<render::ShapeOutline> shape_outline(const v1::Shape& shape);

// A polygon set from the display coordinates (each double converts exactly).
PolygonSet display_polygon_set(const v1::PolygonSet& set);

// The figure of a finished stroke: tip-down samples in mm (device units when the tablet's
// resolution is unknown, said in the caption), its ink, and the shape with its ε-band when
// `shape` is given. Pen radius and tolerance come from the shape's certificate.
render::StrokeFigure stroke_figure(const v1::StrokeFinished& finished, const v1::Shape* shape);

// A file name for a stroke: "stroke-DEVICE-ID.svg" with unsafe characters replaced by '_'.
std::string stroke_file_name(const std::string& device_id, std::uint64_t stroke_id);

} // namespace penshape::cli
