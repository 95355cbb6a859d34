#pragma once
// Reading and rewriting the strokes of a Xournal++ document (the XML inside a .xopp):
// <xournal><page><layer><stroke tool= color= width="w [w1 ... wn]">x0 y0 x1 y1 ...</stroke>.
// The first width is the tool's; the optional others are the pressure widths of the points (one
// per point, or one per segment as older files have). Each layer of each page is one page for
// recognition; pen and highlighter strokes are read, in document order.
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "ink_stroke.hpp"
#include "penshape/core/recognize.hpp"

namespace penshape::snap {

struct XoppStroke {
  InkStroke ink; // in points (the page's unit), radius = width / 2
  pugi::xml_node element;
  std::size_t page = 0, layer = 0, index = 0; // 1-based, for --json and messages
};

struct XoppLayer {
  std::vector<XoppStroke> strokes;
};

// Throws SnapInputError naming page, layer, stroke and line on too few points, bad numbers,
// widths that are not positive or beyond kMaxStrokeWidth, or a pressure count that fits no rule.
std::vector<XoppLayer> read_xopp_strokes(const pugi::xml_document& doc, const std::string& text);

// The stroke becomes the clean shape's polyline (clean_polyline) with the pen width 2
// pen_radius and no pressure; tool, colour and every other attribute stay.
void replace_xopp_stroke(const XoppStroke& stroke, const Recognition& r, double pen_radius);

} // namespace penshape::snap
