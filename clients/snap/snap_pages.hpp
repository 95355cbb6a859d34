#pragma once
// Recognizing every page of a document: writing strokes (page_intent.hpp) are left as drawn and
// part their neighbours, unless SnapSettings::snap_writing; the rest of each page is cut into runs
// of consecutive strokes of the same style (InkStroke::style equal, pen widths within
// kGroupWidthTolerance), since only such strokes may become one shape; the runs are recognized in
// parallel on all cores, and each certified snap comes back in the direction it was drawn. A group
// whose strokes are not consecutive in drawing order is left as drawn.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "ink_stroke.hpp"
#include "page_recognizer.hpp"
#include "penshape/core/intent.hpp"

namespace penshape::snap {

// Two strokes' pen widths (their median radii) count as the same within this fraction of the
// wider.
inline constexpr double kGroupWidthTolerance = 0.10;

// Called as strokes are recognized (from any thread, one call at a time): strokes done, total.
using Progress = std::function<void(std::size_t, std::size_t)>;

struct PageSnap {
  std::size_t page = 0;             // index into the pages given
  std::vector<std::size_t> strokes; // indices into the page, ascending and consecutive
  StrokeSnap snap;
  double pen_radius = 0.0; // the clean shape's
  bool backwards =
      false; // written end to start: an arrow drawn from its head (drawn_direction.hpp)
};

// `pages[p]` are the strokes of page p in drawing order, `intents[p]` their decisions (one per
// stroke, or none: all drawing). A run the recognizer refuses is left as drawn, named in
// `warnings`. Snaps come in page order, then drawing order. `threads` 0: one per core.
std::vector<PageSnap> recognize_pages(const std::vector<std::vector<const InkStroke*>>& pages,
                                      const std::vector<std::vector<IntentDecision>>& intents,
                                      const SnapSettings& settings,
                                      const PageRecognizer& recognize_page,
                                      const Progress& progress, std::size_t threads,
                                      std::vector<std::string>& warnings);

} // namespace penshape::snap
