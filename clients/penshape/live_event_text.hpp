#pragma once
// How the live subcommands print what the daemon sends: one readable line, or one JSON object
// (keys documented in the help of `penshape watch` and `penshape devices`).
#include <string>

#include "json_writer.hpp"
#include "penshape/v1/live.pb.h"

namespace penshape::cli {

// {"id","settings_key","name","vendor_id","product_id","bus","x_max","y_max","pressure_max",
//  "x_resolution","y_resolution","has_tilt","width_mm","height_mm","source","replay"}
void write_device_json(JsonWriter& json, const v1::DeviceInfo& device);
std::string device_line(const v1::DeviceInfo& device);

// The shape's kind as a lowercase word: "square", "circle", "none", ...
std::string shape_kind_name(v1::ShapeKind kind);
// One line: the kind, its main parameters, the confidence and the proven bound H.
std::string shape_summary(const v1::Shape& shape);

// {"kind", "confidence", "vertices":[[x,y],...] | "circle":{...} | "ellipse":{...} | "arc":{...},
//  "hausdorff_bound", "tolerance", "pen_radius"} (mm)
void write_shape_json(JsonWriter& json, const v1::Shape& shape);

// One event: {"sequence","published_us","device_id","type", ...type's fields}.
std::string event_json(const v1::LiveEvent& event);
std::string event_line(const v1::LiveEvent& event);

} // namespace penshape::cli
