// Note pages as SVG and Xournal++ documents (see note_documents.hpp).
#include "note_documents.hpp"

#include <algorithm>
#include <cstdio>

namespace penshape::test::notes {
namespace {

constexpr double kPxPerMm = 96 / 25.4;
constexpr double kPtPerMm = 72 / 25.4;

// "x,y x,y ..." (SVG) or "x y x y ..." (.xopp) in the document's unit; a one-point stroke (a
// dot) is written as two equal points, as the apps write dots.
std::string coordinates(std::vector<StrokePoint> pts, double scale, const char* within) {
  if (pts.size() == 1) pts.push_back(pts.front());
  std::string out;
  char buf[64];
  for (const StrokePoint& p : pts) {
    std::snprintf(buf, sizeof buf, "%s%.3f%s%.3f", out.empty() ? "" : " ", p.x * scale, within,
                  p.y * scale);
    out += buf;
  }
  return out;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

} // namespace

NoteDocument svg_notes(const std::vector<NoteStroke>& page, bool mm_view_box) {
  const double scale = mm_view_box ? 1.0 : kPxPerMm;
  NoteDocument doc;
  doc.xml =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" " +
      std::string(mm_view_box ? "width=\"210mm\" height=\"400mm\" viewBox=\"0 0 210 400\""
                              : "width=\"794\" height=\"1512\"") +
      ">\n";
  for (std::size_t i = 0; i < page.size(); ++i) {
    NoteElement e{"<polyline id=\"s" + std::to_string(i) +
                      "\" fill=\"none\" stroke=\"#000000\" stroke-linecap=\"round\" "
                      "stroke-width=\"" +
                      number(2 * kPenRadiusMm * scale) + "\" points=\"" +
                      coordinates(page[i].points, scale, ",") + "\"/>",
                  page[i].writing};
    doc.xml += e.text + "\n";
    doc.elements.push_back(std::move(e));
  }
  doc.xml += "</svg>\n";
  return doc;
}

NoteDocument xopp_notes(const std::vector<std::vector<NoteStroke>>& pages) {
  NoteDocument doc;
  doc.xml =
      "<?xml version=\"1.0\" standalone=\"no\"?>\n<xournal creator=\"xournalpp 1.1.3\" "
      "fileversion=\"4\">\n<title>Xournal++ document</title>\n";
  for (const auto& page : pages) {
    doc.xml +=
        "<page width=\"595.27559055\" height=\"1133.85826772\">\n<background "
        "type=\"solid\" color=\"#ffffffff\" style=\"lined\"/>\n<layer>\n";
    for (const NoteStroke& s : page) {
      NoteElement e{"<stroke tool=\"pen\" color=\"#000000ff\" width=\"" +
                        number(2 * kPenRadiusMm * kPtPerMm) + "\" capStyle=\"round\">" +
                        coordinates(s.points, kPtPerMm, " ") + "</stroke>",
                    s.writing};
      doc.xml += e.text + "\n";
      doc.elements.push_back(std::move(e));
    }
    doc.xml += "</layer>\n</page>\n";
  }
  doc.xml += "</xournal>\n";
  return doc;
}

std::size_t kept(const NoteDocument& doc, const std::string& output, bool writing) {
  return static_cast<std::size_t>(
      std::count_if(doc.elements.begin(), doc.elements.end(), [&](const NoteElement& e) {
        return e.writing == writing && output.find(e.text) != std::string::npos;
      }));
}

std::size_t count(const NoteDocument& doc, bool writing) {
  return static_cast<std::size_t>(
      std::count_if(doc.elements.begin(), doc.elements.end(),
                    [&](const NoteElement& e) { return e.writing == writing; }));
}

} // namespace penshape::test::notes
