// `penshape snap` in memory (see snap_document.hpp).
#include "snap_document.hpp"

#include <algorithm>
#include <sstream>

#include "gzip.hpp"
#include "snap_error.hpp"
#include "splice.hpp"
#include "svg_writer.hpp"
#include "width_profile.hpp"
#include "xopp_strokes.hpp"
#include "xopp_zip.hpp"

namespace penshape::snap {
namespace {

constexpr unsigned kParse = pugi::parse_full | pugi::parse_ws_pcdata;
constexpr const char* kZipXml = "content.xml";

enum class Packing { kPlain, kGzip, kZip };

std::string root_name(const pugi::xml_document& doc) {
  std::string name = doc.document_element().name();
  const auto colon = name.find(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

// The replaced elements' edits of the text. Offsets into the text are known only for UTF-8 input
// (pugixml converts other encodings); otherwise the document is saved whole from the tree.
struct Splice {
  const std::string& text;
  bool by_offsets = true;
  std::vector<Edit> edits;
};

// Each page's writing/drawing decisions, recorded in the result for --json.
template <typename Stroke>
std::vector<std::vector<IntentDecision>> intents_of(
    const std::vector<std::vector<Stroke>>& pages,
    const std::vector<std::vector<const InkStroke*>>& inks, double mm_per_unit,
    SnapResult& result) {
  std::vector<std::vector<IntentDecision>> intents;
  for (std::size_t p = 0; p < pages.size(); ++p) {
    intents.push_back(page_intents(inks[p], mm_per_unit));
    for (std::size_t i = 0; i < pages[p].size(); ++i) {
      const InkStroke& ink = pages[p][i].ink;
      result.intents.push_back({ink.locator, ink.where, intents.back()[i]});
    }
  }
  return intents;
}

// The pen radii the replacement is written with (width_profile.hpp): a pressure stroke's own, an
// SVG pencil stroke's own stroke width; else the clean pen radius.
std::vector<double> written_radii(const XoppStroke& s, double pen) {
  return s.pressure ? s.ink.radii : std::vector<double>{pen};
}
std::vector<double> written_radii(const SvgStroke& s, double pen) {
  return s.calligraphy ? std::vector<double>{pen} : s.ink.radii;
}

// Whether the snap's certificate holds for the widths drawn and written (widened to them).
template <typename Stroke>
bool certified_as_written(PageSnap& ps, const std::vector<std::vector<Stroke>>& pages) {
  const std::vector<Stroke>& page = pages[ps.page];
  std::vector<double> drawn;
  for (const std::size_t i : ps.strokes) {
    drawn.insert(drawn.end(), page[i].ink.radii.begin(), page[i].ink.radii.end());
  }
  return certify_width_profile(ps.snap.recognition,
                               written_radii(page[ps.strokes.front()], ps.pen_radius), drawn);
}

// The replacement of one snap; writing when every stroke it covers is writing.
template <typename Stroke>
Replacement replacement_of(const PageSnap& ps, const std::vector<std::vector<Stroke>>& pages,
                           const std::vector<std::vector<IntentDecision>>& intents) {
  Replacement rep{{}, {}, ps.snap.recognition, ps.pen_radius, ps.snap.tidy, Intent::kWriting};
  for (const std::size_t i : ps.strokes) {
    const Stroke& s = pages[ps.page][i];
    rep.elements.push_back(s.ink.locator);
    rep.where.push_back(s.ink.where);
    if (intents[ps.page][i].intent == Intent::kDrawing) rep.intent = Intent::kDrawing;
  }
  return rep;
}

// The snaps of the strokes read (mm_per_unit: the page unit's length), each group's elements as
// edits of the text.
template <typename Stroke, typename Replace>
void snap_pages(const std::vector<std::vector<Stroke>>& pages, double mm_per_unit,
                const SnapOptions& options, const PageRecognizer& recognize_page,
                SnapResult& result, Splice& splice, Replace&& replace) {
  std::vector<Edit>& edits = splice.edits;
  std::vector<std::vector<const InkStroke*>> inks(pages.size());
  for (std::size_t p = 0; p < pages.size(); ++p) {
    result.strokes += pages[p].size();
    for (const Stroke& s : pages[p]) inks[p].push_back(&s.ink);
  }
  const auto intents = intents_of(pages, inks, mm_per_unit, result);
  for (PageSnap& ps : recognize_pages(inks, intents, options.settings, recognize_page,
                                      options.progress, options.threads, result.warnings)) {
    if (!certified_as_written(ps, pages)) {
      result.warnings.push_back(pages[ps.page][ps.strokes.front()].ink.where + ": " +
                                to_string(ps.snap.recognition.shape) +
                                " not within the tolerance with the widths drawn: left as drawn");
      continue;
    }
    Replacement rep = replacement_of(ps, pages, intents);
    for (const std::size_t i : ps.strokes) {
      edits.push_back(splice.by_offsets ? element_range(splice.text, pages[ps.page][i].element)
                                        : Edit{});
    }
    // The group's first element becomes the shape; the others go (from the tree too, for a
    // document saved whole).
    edits[edits.size() - ps.strokes.size()].text =
        replace(pages[ps.page][ps.strokes.front()], rep.recognition, ps.pen_radius, ps.backwards);
    for (std::size_t k = 1; k < ps.strokes.size(); ++k) {
      pugi::xml_node gone = pages[ps.page][ps.strokes[k]].element;
      gone.parent().remove_child(gone);
    }
    result.replacements.push_back(std::move(rep));
  }
}

void snap_svg(pugi::xml_document& doc, const std::string& text, const SnapOptions& options,
              const PageRecognizer& recognize_page, SnapResult& result, Splice& splice) {
  result.format = Format::kSvg;
  std::vector<std::vector<SvgStroke>> pages;
  for (SvgPage& page : read_svg_strokes(doc, text, options.scope, result.warnings)) {
    pages.push_back(std::move(page.strokes));
  }
  snap_pages(pages, svg_mm_per_unit(doc.document_element()), options, recognize_page, result,
             splice, [](const SvgStroke& s, const Recognition& r, double pen, bool backwards) {
               return node_text(replace_svg_stroke(s, r, pen, backwards));
             });
}

void snap_xopp(pugi::xml_document& doc, const std::string& text, const SnapOptions& options,
               const PageRecognizer& recognize_page, SnapResult& result, Splice& splice) {
  result.format = Format::kXopp;
  if (!options.scope.ids.empty() || !options.scope.layer.empty()) {
    throw SnapInputError("--ids and --layer choose SVG elements; this is a Xournal++ document");
  }
  std::vector<std::vector<XoppStroke>> pages;
  for (XoppLayer& layer : read_xopp_strokes(doc, text, result.warnings)) {
    pages.push_back(std::move(layer.strokes));
  }
  snap_pages(pages, kXoppMmPerUnit, options, recognize_page, result, splice,
             [](const XoppStroke& s, const Recognition& r, double pen, bool backwards) {
               return replace_xopp_stroke(s, r, pen, backwards);
             });
}

// The whole tree in the input's encoding (its declaration node is kept; BOM for UTF-16/32).
std::string saved(const pugi::xml_document& doc, pugi::xml_encoding encoding) {
  std::ostringstream out;
  const bool wide = encoding != pugi::encoding_utf8 && encoding != pugi::encoding_latin1;
  doc.save(out, "",
           pugi::format_raw | pugi::format_no_declaration | (wide ? pugi::format_write_bom : 0u),
           encoding);
  return out.str();
}

// The XML inside the bytes, and how it was packed.
std::string unpack(const std::string& bytes, Packing& packing) {
  if (looks_zipped(bytes)) {
    packing = Packing::kZip;
    return zip_entry(bytes, kZipXml, kMaxXmlBytes);
  }
  if (looks_gzipped(bytes)) {
    packing = Packing::kGzip;
    return gunzip(bytes, kMaxXmlBytes);
  }
  packing = Packing::kPlain;
  return bytes;
}

std::string pack(const std::string& original, const std::string& xml, Packing packing) {
  switch (packing) {
    case Packing::kZip:
      return zip_with_entry(original, kZipXml, xml);
    case Packing::kGzip:
      return gzip(xml);
    default:
      return xml;
  }
}

} // namespace

std::size_t line_of(std::string_view text, std::ptrdiff_t offset) {
  return LineIndex(text).line(offset);
}

LineIndex::LineIndex(std::string_view text) {
  for (std::size_t at = text.find('\n'); at != std::string_view::npos;
       at = text.find('\n', at + 1)) {
    newlines_.push_back(at);
  }
}

std::size_t LineIndex::line(std::ptrdiff_t offset) const {
  if (offset < 0) return 0;
  const auto before =
      std::lower_bound(newlines_.begin(), newlines_.end(), static_cast<std::size_t>(offset));
  return 1 + static_cast<std::size_t>(before - newlines_.begin());
}

SnapResult snap_document(const std::string& bytes, const SnapOptions& options,
                         const PageRecognizer& recognize_page) {
  Packing packing = Packing::kPlain;
  const std::string text = unpack(bytes, packing);
  const char* what = packing == Packing::kZip    ? "the zip's content.xml"
                     : packing == Packing::kGzip ? "the gzip's content"
                                                 : "the file";
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size(), kParse);
  if (!parsed) {
    throw SnapInputError(std::string(what) + " is not well-formed XML: line " +
                         std::to_string(line_of(text, parsed.offset)) + ": " +
                         parsed.description());
  }
  SnapResult result;
  Splice splice{text, parsed.encoding == pugi::encoding_utf8, {}};
  const std::string root = root_name(doc);
  if (root == "svg") {
    snap_svg(doc, text, options, recognize_page, result, splice);
  } else if (root == "xournal") {
    snap_xopp(doc, text, options, recognize_page, result, splice);
  } else {
    throw SnapInputError(std::string(what) + " is XML of neither format: its root is <" +
                         doc.document_element().name() +
                         ">, not <svg> (SVG) or <xournal> (Xournal++)");
  }
  if (splice.edits.empty()) {
    result.output = bytes;
  } else {
    const std::string xml =
        splice.by_offsets ? spliced(text, splice.edits) : saved(doc, parsed.encoding);
    result.output = pack(bytes, xml, packing);
  }
  return result;
}

} // namespace penshape::snap
