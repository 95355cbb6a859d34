#pragma once
// The shipped recognizer per class on labelled real drawings (recognize_bench --classes,
// --wrong): every shape and non-shape class of each corpus with its rate, the diamonds and
// squares on a corner made from real one-stroke rectangles, the polygons of 5-8 corners made from
// real one-stroke circles, one-stroke stars, every class simplified as sketch collections store
// drawings, and on request every miss.
#include <vector>

#include "stroke_corpora.hpp"

namespace penshape::bench {

struct ClassOptions {
  bool list_wrong = false; // also print every drawing named wrong, with the class given
};

// Prints the per-class table (and the misses) for the drawings with the shipped defaults.
void print_classes(const std::vector<Drawing>& drawings, const ClassOptions& options);

} // namespace penshape::bench
