// `penshape snap` in memory (see snap_document.hpp).
#include "snap_document.hpp"

#include <cstring>
#include <sstream>

#include "clean_shape.hpp"
#include "gzip.hpp"
#include "snap_error.hpp"
#include "svg_writer.hpp"
#include "xopp_strokes.hpp"

namespace penshape::snap {
namespace {

constexpr unsigned kParse = pugi::parse_full | pugi::parse_ws_pcdata;

std::string root_name(const pugi::xml_document& doc) {
  std::string name = doc.document_element().name();
  const auto colon = name.find(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

bool has_distinct_points(const InkStroke& s) {
  for (const auto& p : s.points) {
    if (p.x != s.points.front().x || p.y != s.points.front().y) return true;
  }
  return false;
}

// Recognizes one page; calls replace(strokes, snap, pen_radius) for each snap.
template <typename Stroke, typename Replace>
void snap_page(const std::vector<Stroke>& strokes, const SnapOptions& options,
               const PageRecognizer& recognize_page, Replace&& replace) {
  std::vector<const Stroke*> kept;
  std::vector<InkStroke> inks;
  for (const Stroke& s : strokes) {
    if (!has_distinct_points(s.ink)) continue; // a dot: nothing to snap
    kept.push_back(&s);
    inks.push_back(s.ink);
  }
  if (inks.empty()) return;
  for (const StrokeSnap& snap : recognize_page(inks, options.settings)) {
    if (!is_snap(snap.recognition)) continue;
    std::vector<const Stroke*> group;
    for (const std::size_t i : snap.strokes) group.push_back(kept.at(i));
    replace(group, snap, clean_pen_radius(inks[snap.strokes.front()], options.settings));
  }
}

std::string saved(const pugi::xml_document& doc) {
  std::ostringstream out;
  doc.save(out, "", pugi::format_raw | pugi::format_no_declaration, pugi::encoding_utf8);
  return out.str();
}

void snap_svg(pugi::xml_document& doc, const std::string& text, const SnapOptions& options,
              const PageRecognizer& recognize_page, SnapResult& result) {
  result.format = Format::kSvg;
  for (const SvgPage& page : read_svg_strokes(doc, text, options.scope)) {
    result.strokes += page.strokes.size();
    snap_page(page.strokes, options, recognize_page,
              [&](const std::vector<const SvgStroke*>& group, const StrokeSnap& snap, double pen) {
                const Recognition& r = snap.recognition;
                Replacement rep{{}, {}, r, pen, snap.tidy};
                for (const SvgStroke* s : group) {
                  rep.elements.push_back(s->element.attribute("id").value());
                  rep.where.push_back(s->ink.where);
                }
                replace_svg_stroke(*group.front(), r, pen);
                for (std::size_t i = 1; i < group.size(); ++i) {
                  group[i]->element.parent().remove_child(group[i]->element);
                }
                result.replacements.push_back(std::move(rep));
              });
  }
}

void snap_xopp(pugi::xml_document& doc, const std::string& text, const SnapOptions& options,
               const PageRecognizer& recognize_page, SnapResult& result) {
  result.format = Format::kXopp;
  if (!options.scope.ids.empty() || !options.scope.layer.empty()) {
    throw SnapInputError("--ids and --layer choose SVG elements; this is a Xournal++ document");
  }
  for (const XoppLayer& layer : read_xopp_strokes(doc, text)) {
    result.strokes += layer.strokes.size();
    snap_page(layer.strokes, options, recognize_page,
              [&](const std::vector<const XoppStroke*>& group, const StrokeSnap& snap, double pen) {
                const Recognition& r = snap.recognition;
                Replacement rep{{}, {}, r, pen, snap.tidy};
                for (const XoppStroke* s : group) {
                  rep.elements.push_back("page " + std::to_string(s->page) + " layer " +
                                         std::to_string(s->layer) + " stroke " +
                                         std::to_string(s->index));
                  rep.where.push_back(s->ink.where);
                }
                replace_xopp_stroke(*group.front(), r, pen);
                for (std::size_t i = 1; i < group.size(); ++i) {
                  group[i]->element.parent().remove_child(group[i]->element);
                }
                result.replacements.push_back(std::move(rep));
              });
  }
}

} // namespace

std::size_t line_of(std::string_view text, std::ptrdiff_t offset) {
  if (offset < 0) return 0;
  const auto end = std::min(text.size(), static_cast<std::size_t>(offset));
  std::size_t line = 1;
  for (std::size_t i = 0; i < end; ++i) line += text[i] == '\n' ? 1 : 0;
  return line;
}

SnapResult snap_document(const std::string& bytes, const SnapOptions& options,
                         const PageRecognizer& recognize_page) {
  const bool gzipped = looks_gzipped(bytes);
  const std::string text = gzipped ? gunzip(bytes) : bytes;
  const char* what = gzipped ? "the gzip's content" : "the file";
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size(), kParse);
  if (!parsed) {
    throw SnapInputError(std::string(what) + " is not well-formed XML: line " +
                         std::to_string(line_of(text, parsed.offset)) + ": " +
                         parsed.description());
  }
  SnapResult result;
  const std::string root = root_name(doc);
  if (root == "svg") {
    snap_svg(doc, text, options, recognize_page, result);
  } else if (root == "xournal") {
    snap_xopp(doc, text, options, recognize_page, result);
  } else {
    throw SnapInputError(std::string(what) + " is XML of neither format: its root is <" +
                         doc.document_element().name() +
                         ">, not <svg> (SVG) or <xournal> (Xournal++)");
  }
  result.output = result.replacements.empty() ? text : saved(doc);
  if (gzipped) result.output = gzip(result.output);
  return result;
}

} // namespace penshape::snap
