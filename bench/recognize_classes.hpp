#pragma once
// The shipped recognizer per class on labelled real drawings (recognize_bench --classes,
// --wrong): every shape and non-shape class of each corpus with its rate, the diamonds and
// squares on a corner made from real one-stroke rectangles, and on request every miss.
#include <vector>

#include "stroke_corpora.hpp"

namespace penshape::bench {

struct ClassOptions {
  bool list_wrong = false; // also print every drawing named wrong, with the class given
};

// The stroke's box to the unit square (x 100), turned 45 degrees, stretched by `across` along y:
// a real one-stroke rectangle made a diamond (across < 1) or a square on its corner (across = 1).
std::vector<StrokePoint> on_corner(const std::vector<StrokePoint>& in, double across);
inline constexpr double kDiamondAcross = 0.6; // half-diagonal ratio of the made diamonds (62 deg)

// Prints the per-class table (and the misses) for the drawings with the shipped defaults.
void print_classes(const std::vector<Drawing>& drawings, const ClassOptions& options);

} // namespace penshape::bench
