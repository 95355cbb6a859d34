#pragma once
// `penshape snap` on a document in memory: the format found by content (gzip or plain XML with a
// <xournal> root: Xournal++; an <svg> root: SVG), the strokes of each page recognized in drawing
// order, the snapped ones replaced, everything else kept byte for byte where the XML library
// allows (comments, processing instructions, whitespace and attribute order are kept).
#include <string>
#include <vector>

#include "page_recognizer.hpp"
#include "svg_strokes.hpp"

namespace penshape::snap {

enum class Format { kSvg, kXopp };

// One snapped stroke (or group): where it was, and the answer.
struct Replacement {
  std::vector<std::string> elements; // SVG element ids ("" when none) or "page P layer L stroke S"
  std::vector<std::string> where;    // as in messages, with line numbers
  Recognition recognition;
  double pen_radius = 0.0;       // the clean shape's
  std::vector<std::string> tidy; // tidy-up constraints applied ("axis", "right_angles", ...)
};

struct SnapResult {
  Format format = Format::kSvg;
  std::string output; // the new document's bytes (gzip for .xopp that came gzipped)
  std::vector<Replacement> replacements;
  std::size_t strokes = 0; // strokes read
};

struct SnapOptions {
  SnapSettings settings;
  SvgScope scope; // SVG only
};

// Throws SnapInputError for bad input (the message names the place).
SnapResult snap_document(const std::string& bytes, const SnapOptions& options,
                         const PageRecognizer& recognize_page);

} // namespace penshape::snap
