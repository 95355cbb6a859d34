#pragma once
// Note pages (writing with shapes drawn between the lines, in millimetres) written as the
// documents `penshape snap` reads, each stroke one element whose exact text is kept, so a test
// can tell which strokes came out byte for byte.
#include <string>
#include <vector>

#include "penshape/core/recognize.hpp" // StrokePoint

namespace penshape::test::notes {

struct NoteStroke {
  std::vector<StrokePoint> points; // millimetres, y down
  bool writing = true;
};

struct NoteElement {
  std::string text; // the element exactly as written into the document
  bool writing = true;
};

struct NoteDocument {
  std::string xml;
  std::vector<NoteElement> elements; // one per stroke, in drawing order
};

// Pen 0.35 mm in radius, as the writing issue's pages.
inline constexpr double kPenRadiusMm = 0.35;

// An SVG page; with `mm_view_box`, width in mm and a viewBox of one user unit per mm, else
// user units in CSS pixels (no viewBox).
NoteDocument svg_notes(const std::vector<NoteStroke>& page, bool mm_view_box);

// A Xournal++ document (plain XML): every entry of `pages` one page of one layer, in points.
NoteDocument xopp_notes(const std::vector<std::vector<NoteStroke>>& pages);

// Of the elements with this intent, how many appear in `output` exactly as written.
std::size_t kept(const NoteDocument& doc, const std::string& output, bool writing);
std::size_t count(const NoteDocument& doc, bool writing);

} // namespace penshape::test::notes
