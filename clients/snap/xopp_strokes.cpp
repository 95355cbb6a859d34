// Xournal++ strokes in and out (see xopp_strokes.hpp).
#include "xopp_strokes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include "clean_shape.hpp"
#include "number_scanner.hpp"
#include "snap_error.hpp"
#include "splice.hpp"

namespace penshape::snap {
namespace {

std::string place(std::size_t page, std::size_t layer, std::size_t index, const pugi::xml_node& n,
                  const LineIndex& lines) {
  return "page " + std::to_string(page) + " layer " + std::to_string(layer) + " stroke " +
         std::to_string(index) + " (line " + std::to_string(lines.line(n.offset_debug())) + ")";
}

// A stroke snap leaves as drawn, and why (empty: silently, as for a dot).
struct NotAStroke {
  std::string why;
};

std::vector<double> numbers(const char* s, const char* what) {
  NumberScanner in(s);
  std::vector<double> out;
  for (in.skip_separators(); !in.done(); in.skip_separators()) {
    const auto v = in.number();
    if (!v) throw NotAStroke{std::string("bad number in ") + what + " at offset " + in.where()};
    out.push_back(*v);
  }
  return out;
}

// The pressure widths as Xournal++ keeps them: one per segment of the first `count` points.
std::vector<double> segment_pressures(std::vector<double> w, std::size_t& count) {
  std::vector<double> p(w.begin() + 1, w.end());
  if (p.empty()) return p;
  count = std::min(count, p.size() + 1); // too few widths: the stroke ends where they do
  p.resize(count - 1);                   // one per point: the last point's is dropped
  return p;
}

// The first run of segments of positive pressure, as [first, last] point indices; throws when
// none is drawn or several are.
std::pair<std::size_t, std::size_t> drawn_run(const std::vector<double>& p) {
  const auto positive = [](double v) { return v > 0; };
  const auto begin = std::find_if(p.begin(), p.end(), positive);
  if (begin == p.end()) throw NotAStroke{""}; // invisible in Xournal++
  const auto end = std::find_if_not(begin, p.end(), positive);
  if (std::find_if(end, p.end(), positive) != p.end()) {
    throw NotAStroke{"drawn in pieces (pressure <= 0 between them)"};
  }
  return {static_cast<std::size_t>(begin - p.begin()), static_cast<std::size_t>(end - p.begin())};
}

void check_width(double v) {
  if (!(v > 0) || v > kMaxStrokeWidth) {
    throw NotAStroke{"width " + std::to_string(v) + " is beyond what snap redraws (wider than 0 " +
                     "and at most " + std::to_string(static_cast<int>(kMaxStrokeWidth)) + " pt)"};
  }
}

// The pen path and radii Xournal++ draws for the element.
void read_ink(const pugi::xml_node& n, XoppStroke& s) {
  const std::vector<double> xy = numbers(n.child_value(), "the points");
  if (xy.size() % 2 != 0) throw NotAStroke{"odd count of coordinates"};
  std::size_t count = xy.size() / 2;
  const std::vector<double> w = numbers(n.attribute("width").value(), "width");
  if (w.empty()) throw NotAStroke{"no width"};
  const std::vector<double> p = segment_pressures(w, count);
  if (count < 2) throw NotAStroke{""}; // a dot (or nothing): nothing to snap
  std::size_t first = 0, last = count - 1;
  if (!p.empty()) std::tie(first, last) = drawn_run(p);
  s.pressure = !p.empty();
  for (std::size_t i = first; i <= last; ++i) {
    const double width = p.empty() ? w[0] : p[std::min(i, last - 1)];
    check_width(width);
    s.ink.points.push_back({xy[2 * i], xy[2 * i + 1], static_cast<double>(i - first)});
    s.ink.radii.push_back(width / 2);
  }
  if (!coordinates_in_range(s.ink.points)) {
    throw NotAStroke{"coordinates beyond +-1e6 pt or not finite"};
  }
}

std::optional<XoppStroke> read_stroke(const pugi::xml_node& n, std::size_t page, std::size_t layer,
                                      std::size_t index, const LineIndex& lines,
                                      std::vector<std::string>& warnings) {
  XoppStroke s;
  s.element = n;
  s.page = page, s.layer = layer, s.index = index;
  s.ink.where = place(page, layer, index, n, lines);
  s.ink.locator = "/xournal/page[" + std::to_string(page) + "]/layer[" + std::to_string(layer) +
                  "]/stroke[" + std::to_string(index) + "]";
  s.ink.style = std::string(n.attribute("tool").as_string("pen")) + " " +
                n.attribute("color").value() + " fill " + n.attribute("fill").value();
  try {
    read_ink(n, s);
  } catch (const NotAStroke& e) {
    if (!e.why.empty()) warnings.push_back(s.ink.where + ": " + e.why + ": left as drawn");
    return std::nullopt;
  }
  return s;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

// Each new point's pressure width: the old stroke's radius at the same fraction of its length.
std::string pressure_widths(const InkStroke& ink, const std::vector<PointD>& pts) {
  const auto lengths = [](const auto& v) {
    std::vector<double> out{0};
    for (std::size_t i = 1; i < v.size(); ++i) {
      out.push_back(out.back() + std::hypot(v[i].x - v[i - 1].x, v[i].y - v[i - 1].y));
    }
    return out;
  };
  const std::vector<double> old_len = lengths(ink.points), new_len = lengths(pts);
  std::string out;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double f = new_len.back() > 0 ? new_len[i] / new_len.back() : 0;
    const auto at = std::lower_bound(old_len.begin(), old_len.end(), f * old_len.back());
    const auto k = std::min(static_cast<std::size_t>(at - old_len.begin()), ink.radii.size() - 1);
    out.append(" ").append(num(2 * ink.radii[k]));
  }
  return out;
}

} // namespace

std::vector<XoppLayer> read_xopp_strokes(const pugi::xml_document& doc, const std::string& text,
                                         std::vector<std::string>& warnings) {
  const LineIndex lines(text);
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
        if (auto s = read_stroke(n, page, layer, index, lines, warnings)) {
          strokes.strokes.push_back(std::move(*s));
        }
      }
      out.push_back(std::move(strokes));
    }
  }
  return out;
}

namespace {

// Writes one line of the clean shape into the stroke element n.
void write_line(pugi::xml_node n, const XoppStroke& stroke, const std::vector<PointD>& clean,
                double pen_radius) {
  std::string pts;
  for (const PointD& p : clean) {
    if (!pts.empty()) pts += ' ';
    pts.append(num(p.x)).append(" ").append(num(p.y));
  }
  std::string width = num(2 * pen_radius);
  if (stroke.pressure) width += pressure_widths(stroke.ink, clean);
  n.attribute("width").set_value(width.c_str());
  while (n.first_child()) n.remove_child(n.first_child());
  n.append_child(pugi::node_pcdata).set_value(pts.c_str());
}

} // namespace

std::string replace_xopp_stroke(const XoppStroke& stroke, const Recognition& r, double pen_radius,
                                bool backwards) {
  std::vector<std::vector<PointD>> lines = clean_lines(r);
  if (backwards) {
    std::reverse(lines.begin(), lines.end());
    for (std::vector<PointD>& line : lines) std::reverse(line.begin(), line.end());
  }
  // A stroke is one line: a shape of two pieces (an arrow whose shaft stops short of its tip)
  // writes its second piece as a copy of the stroke just after it.
  pugi::xml_node n = stroke.element;
  std::string text;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    if (k > 0) n = n.parent().insert_copy_after(n, n);
    write_line(n, stroke, lines[k], pen_radius);
    text += node_text(n);
  }
  return text;
}

} // namespace penshape::snap
