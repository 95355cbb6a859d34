#pragma once
// Writing a snapped stroke back into its SVG: the element is replaced, at the same place in its
// parent (same layer, same z-order), by a native element of the clean shape (rect, circle,
// ellipse, line, polyline, polygon, path with true arcs, or for an arrow a path of its shaft
// through its bends, its head and a double arrow's tail head), in the element's own coordinates so
// that its transform, id, class and style stay. A calligraphy outline becomes a stroked shape of
// the outline's colour and the estimated pen width. The new element names the class and the
// certificate in data-penshape-class and data-penshape-certificate.
#include "penshape/core/recognize.hpp"
#include "svg_strokes.hpp"

namespace penshape::snap {

// `pen_radius` is the clean shape's pen radius (root units). `backwards`: an arrow's path is
// written end to start (drawn head first, drawn_direction.hpp: the head's piece, reversed, then
// the shaft from tip to tail). Returns the new element.
pugi::xml_node replace_svg_stroke(const SvgStroke& stroke, const Recognition& r, double pen_radius,
                                  bool backwards = false);

} // namespace penshape::snap
