#pragma once
// Reading and rewriting the strokes of a Xournal++ document (the XML inside a .xopp):
// <xournal><page><layer><stroke tool= color= width="w [p0 ... pk]">x0 y0 x1 y1 ...</stroke>.
// Read as Xournal++ reads them: the first width is the tool's; the others are pressure widths,
// the i-th for the segment from point i (the last point has none; extra widths are dropped, and
// with too few the stroke ends where they do); a segment of pressure <= 0 is not drawn, so the
// stroke is the run of points it draws. Each layer of each page is one page for recognition; pen
// and highlighter strokes are read, in document order.
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
  bool pressure = false;                      // drawn with per-segment pressure widths
};

struct XoppLayer {
  std::vector<XoppStroke> strokes;
};

// Never throws for a stroke: one that Xournal++ draws but snap cannot read as one pen path (bad
// numbers, widths out of range, coordinates beyond kMaxCoordinate, drawn in several pieces) is
// left as drawn and named in `warnings`; a dot (one point) and an invisible stroke are left
// silently.
std::vector<XoppLayer> read_xopp_strokes(const pugi::xml_document& doc, const std::string& text,
                                         std::vector<std::string>& warnings);

// The stroke becomes the clean shape's polyline (clean_lines) with the pen width 2
// pen_radius; a pressure stroke keeps its width profile (each new point takes the width found
// at the same fraction of the old stroke's length). Tool, colour and every other attribute stay.
// `backwards`: the polyline is written end to start (an arrow drawn head first,
// drawn_direction.hpp). An arrow whose shaft stops short of its tip is two lines: the second is
// written into a copy of the stroke inserted after it. Returns the XML text written (the
// stroke, and the copy when there is one).
std::string replace_xopp_stroke(const XoppStroke& stroke, const Recognition& r, double pen_radius,
                                bool backwards = false);

} // namespace penshape::snap
