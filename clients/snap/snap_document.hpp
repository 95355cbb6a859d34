#pragma once
// `penshape snap` on a document in memory: the format found by content (an <svg> root: SVG; a
// <xournal> root, plain, gzipped or as content.xml of a zip package: Xournal++), the strokes of
// each page recognized in drawing order (pages in parallel), and the snapped ones replaced by
// splicing the new elements into the original text: every byte outside a replaced element
// (whitespace, comments, entities, other attributes) comes out as it came in, and a document with
// nothing snapped comes out byte for byte. Writing strokes (page_intent.hpp) are left as drawn
// unless SnapSettings::snap_writing.
#include <string>
#include <vector>

#include "page_intent.hpp"
#include "page_recognizer.hpp"
#include "snap_pages.hpp"
#include "svg_strokes.hpp"

namespace penshape::snap {

enum class Format { kSvg, kXopp };

// One snapped stroke (or group): where it was, and the answer.
struct Replacement {
  std::vector<std::string> elements; // stable locators: the id, else "/svg[1]/g[2]/path[1]"
  std::vector<std::string> where;    // as in messages, with line numbers
  Recognition recognition;
  double pen_radius = 0.0;          // the clean shape's
  std::vector<std::string> tidy;    // tidy-up constraints applied ("axis", "right_angles", ...)
  Intent intent = Intent::kDrawing; // writing (only with snap_writing) if all its strokes are
};

// Every stroke read, with its writing/drawing decision.
struct StrokeIntent {
  std::string element; // stable locator
  std::string where;
  IntentDecision decision;
};

struct SnapResult {
  Format format = Format::kSvg;
  std::string output; // the new document's bytes (packed as the input was)
  std::vector<Replacement> replacements;
  std::vector<std::string> warnings; // elements left as drawn because snap cannot read them
  std::size_t strokes = 0;           // strokes read
  std::vector<StrokeIntent> intents; // one per stroke read, pages in order, drawing order
};

struct SnapOptions {
  SnapSettings settings;
  SvgScope scope;          // SVG only
  Progress progress;       // optional
  std::size_t threads = 0; // recognizing in parallel; 0: one per core
};

// The largest XML a compressed document may expand to (gzip or zip); past it reading stops.
inline constexpr std::size_t kMaxXmlBytes = std::size_t{1} << 30;

// Throws SnapInputError only for a document the apps cannot open either (not XML, neither
// format, corrupt compression, past kMaxXmlBytes) or a scope that names nothing; the message
// names the place.
SnapResult snap_document(const std::string& bytes, const SnapOptions& options,
                         const PageRecognizer& recognize_page);

} // namespace penshape::snap
