#pragma once
// What the writing/drawing decision reads from a stroke's context: the strokes drawn just before
// and after it (a window in drawing order), as their measures.
#include <cstddef>
#include <span>

#include "stroke_measures.hpp"

namespace penshape::intent {

struct Context {
  double writing_height = 0.0; // the context's typical writing height, mm
  int near = 0;                // strokes whose boxes come within one writing height
  int on_line = 0;             // strokes on the same text line, at most 3 heights away
  int inside = 0;              // strokes whose box centre lies inside this stroke's box
  double gap = 0.0;            // to the nearest stroke's box, in writing heights (capped)
  double small_run = 0.5;      // share of the 3 strokes before and after that are letter-sized
  double pause = 0.0;          // the shorter pen-up pause before or after, s (when timed)
};

// The context of stroke `i` among `all` (the page's measures), within `window` strokes.
Context context_of(std::span<const StrokeMeasures> all, std::size_t i, std::size_t window);

} // namespace penshape::intent
