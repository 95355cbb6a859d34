#pragma once
// Reading the strokes of an SVG drawing (as Inkscape writes it, or plain SVG): each layer
// (`g` with inkscape:groupmode="layer", or the root for content outside layers) is one page, its
// strokes in document order. A stroke is a path, polyline, polygon or line that is stroked and not
// filled (Pencil, Pen, Bezier tools; a closed subpath keeps its closing side), or a filled,
// unstroked path of one closed subpath of nearly constant width (the Calligraphy tool's outline,
// read back by outline_centerline.hpp). Everything else is left alone. The tree is walked without
// recursion, so any nesting depth the XML parser accepts is read.
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "ink_stroke.hpp"
#include "snap_error.hpp"
#include "transform.hpp"

namespace penshape::snap {

// Which part of the drawing to read: the elements with these ids (a group or layer means what it
// contains), or one layer, or (both empty) everything.
struct SvgScope {
  std::vector<std::string> ids;
  std::string layer;
};

struct SvgStroke {
  InkStroke ink;          // in the root's user units
  pugi::xml_node element; // the element to replace
  Affine to_root;         // the element's coordinates (own transform included) to the root's
  bool calligraphy = false;
};

struct SvgPage {
  std::string name; // the layer's label or id, "root" for content outside layers
  std::vector<SvgStroke> strokes;
};

// `text` is the file the document was parsed from (for line numbers in messages). An element that
// looks like a stroke but cannot be read as one (bad geometry, transform or width, one point,
// coordinates beyond kMaxCoordinate) is left as drawn and named in `warnings`. Throws
// SnapInputError only for scope ids that name nothing.
std::vector<SvgPage> read_svg_strokes(const pugi::xml_document& doc, const std::string& text,
                                      const SvgScope& scope, std::vector<std::string>& warnings);

// The element's stable name: its id, else an XPath-like path ("/svg[1]/g[2]/path[1]").
std::string locator(const pugi::xml_node& element);

// "path#id (line 12)" for messages.
std::string describe(const pugi::xml_node& element, const LineIndex& lines);

} // namespace penshape::snap
