#pragma once
// Writing or drawing, for the strokes of a document's page (core intent.hpp): the decision needs
// millimetres, so each format says how long its unit is; a writing stroke is then never snapped
// nor grouped, and stays byte for byte (snap_pages.hpp).
#include <vector>

#include <pugixml.hpp>

#include "ink_stroke.hpp"
#include "penshape/core/intent.hpp"

namespace penshape::snap {

// Xournal++ pages are in PostScript points.
inline constexpr double kXoppMmPerUnit = 25.4 / 72;
// An SVG user unit is a CSS pixel unless the root's viewBox and width say otherwise.
inline constexpr double kSvgPixelMm = 25.4 / 96;

// Millimetres per user unit of the root <svg>: its width (a length in mm, cm, in, pt, pc or px)
// over its viewBox width when both are given, else a CSS pixel (a width in % or none says
// nothing about the size).
double svg_mm_per_unit(const pugi::xml_node& svg);

// One decision per stroke of the page, in drawing order (documents keep no times, so the strokes
// are taken as untimed). A page the decision cannot measure is all drawing (snapped as before).
std::vector<IntentDecision> page_intents(const std::vector<const InkStroke*>& page,
                                         double mm_per_unit);

} // namespace penshape::snap
