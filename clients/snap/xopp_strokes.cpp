// Xournal++ strokes in and out (see xopp_strokes.hpp).
#include "xopp_strokes.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "clean_shape.hpp"
#include "number_scanner.hpp"
#include "snap_error.hpp"

namespace penshape::snap {
namespace {

std::string place(std::size_t page, std::size_t layer, std::size_t index, const pugi::xml_node& n,
                  const std::string& text) {
  return "page " + std::to_string(page) + " layer " + std::to_string(layer) + " stroke " +
         std::to_string(index) + " (line " + std::to_string(line_of(text, n.offset_debug())) + ")";
}

std::vector<double> numbers(const char* s, const std::string& where, const char* what) {
  NumberScanner in(s);
  std::vector<double> out;
  for (in.skip_separators(); !in.done(); in.skip_separators()) {
    const auto v = in.number();
    if (!v) throw SnapInputError(where + ": bad number in " + what + " at offset " + in.where());
    out.push_back(*v);
  }
  return out;
}

XoppStroke read_stroke(const pugi::xml_node& n, std::size_t page, std::size_t layer,
                       std::size_t index, const std::string& text) {
  XoppStroke s;
  s.element = n;
  s.page = page, s.layer = layer, s.index = index;
  s.ink.where = place(page, layer, index, n, text);
  const std::vector<double> xy = numbers(n.child_value(), s.ink.where, "the points");
  if (xy.size() % 2 != 0) throw SnapInputError(s.ink.where + ": odd count of coordinates");
  const std::size_t count = xy.size() / 2;
  if (count < 2) {
    throw SnapInputError(s.ink.where + ": a stroke with " + std::to_string(count) +
                         " point(s); a stroke needs at least 2");
  }
  const std::vector<double> w = numbers(n.attribute("width").value(), s.ink.where, "width");
  if (w.empty()) throw SnapInputError(s.ink.where + ": no width");
  for (const double v : w) {
    if (!(v > 0) || v > kMaxStrokeWidth) {
      throw SnapInputError(s.ink.where + ": width " + std::to_string(v) +
                           " is absurd (a pen is wider than 0 and at most " +
                           std::to_string(static_cast<int>(kMaxStrokeWidth)) + " pt)");
    }
  }
  const std::size_t pressures = w.size() - 1;
  if (pressures != 0 && pressures != count && pressures != count - 1) {
    throw SnapInputError(s.ink.where + ": " + std::to_string(pressures) + " pressure widths for " +
                         std::to_string(count) + " points");
  }
  for (std::size_t i = 0; i < count; ++i) {
    s.ink.points.push_back({xy[2 * i], xy[2 * i + 1], static_cast<double>(i)});
    const double width = pressures == 0 ? w[0] : w[1 + std::min(i, pressures - 1)];
    s.ink.radii.push_back(width / 2);
  }
  return s;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

} // namespace

std::vector<XoppLayer> read_xopp_strokes(const pugi::xml_document& doc, const std::string& text) {
  std::vector<XoppLayer> out;
  std::size_t page = 0;
  for (const pugi::xml_node& p : doc.document_element().children("page")) {
    ++page;
    std::size_t layer = 0;
    for (const pugi::xml_node& l : p.children("layer")) {
      ++layer;
      XoppLayer strokes;
      std::size_t index = 0;
      for (const pugi::xml_node& n : l.children("stroke")) {
        ++index;
        const char* tool = n.attribute("tool").as_string("pen");
        if (std::strcmp(tool, "pen") != 0 && std::strcmp(tool, "highlighter") != 0) continue;
        strokes.strokes.push_back(read_stroke(n, page, layer, index, text));
      }
      out.push_back(std::move(strokes));
    }
  }
  return out;
}

void replace_xopp_stroke(const XoppStroke& stroke, const Recognition& r, double pen_radius) {
  pugi::xml_node n = stroke.element;
  std::string pts;
  for (const PointD& p : clean_polyline(r)) {
    if (!pts.empty()) pts += ' ';
    pts.append(num(p.x)).append(" ").append(num(p.y));
  }
  n.attribute("width").set_value(num(2 * pen_radius).c_str());
  while (n.first_child()) n.remove_child(n.first_child());
  n.append_child(pugi::node_pcdata).set_value(pts.c_str());
}

} // namespace penshape::snap
