#pragma once
// Reading the strokes of an SVG drawing (as Inkscape writes it, or plain SVG): each layer
// (`g` with inkscape:groupmode="layer", or the root for content outside layers) is one page, its
// strokes in document order. A stroke is a path, polyline or line that is stroked and not filled
// (Pencil, Pen, Bezier tools), or a filled, unstroked path of one closed subpath (the Calligraphy
// tool's outline, read back by outline_centerline.hpp). Everything else is left alone.
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "ink_stroke.hpp"
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

// `text` is the file the document was parsed from (for line numbers in messages). Throws
// SnapInputError naming the line and element id on bad geometry or widths, or unknown scope ids.
std::vector<SvgPage> read_svg_strokes(const pugi::xml_document& doc, const std::string& text,
                                      const SvgScope& scope);

// "path#id (line 12)" for messages.
std::string describe(const pugi::xml_node& element, const std::string& text);

} // namespace penshape::snap
