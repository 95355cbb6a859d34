#pragma once
// Recognizing the strokes of one page in drawing order: the single step of `penshape snap` that
// decides which strokes (or groups of strokes) become which clean shapes. Today each stroke is
// recognized on its own with the core's single-stroke recognizer and its ink certificate; when
// the core groups recent strokes, only recognize_page changes.
#include <cstddef>
#include <functional>
#include <vector>

#include "ink_stroke.hpp"
#include "penshape/core/recognize.hpp"

namespace penshape::snap {

struct SnapSettings {
  double pen_radius = 0.0; // page units; <= 0: each stroke's own (median) radius
  double tolerance = 0.0;  // page units; <= 0: the recognizer's rule (recognize.hpp)
  bool group = true;       // may strokes be grouped (no effect until the core groups)
};

// The answer for `count` consecutive strokes from `first` (count is 1 until grouping lands).
struct StrokeSnap {
  std::size_t first = 0;
  std::size_t count = 1;
  Recognition recognition; // in page units
};

// One stroke's recognition: in-process (recognize_in_process) or through penshaped.
using StrokeRecognizer = std::function<Recognition(const InkStroke&, const SnapSettings&)>;

// Every stroke of the page, in order, with its answer (freeform included).
std::vector<StrokeSnap> recognize_page(const std::vector<InkStroke>& page,
                                       const SnapSettings& settings,
                                       const StrokeRecognizer& recognize_one);

// The core in this process: the stroke's ink polygon from its points and radii, and the
// recognition certified on it (Certificate::method "ink"). The clean shape's pen radius is the
// settings' radius, else the median of the stroke's radii.
Recognition recognize_in_process(const InkStroke& stroke, const SnapSettings& settings);

// The pen radius the clean shape is drawn with (the rule above).
double clean_pen_radius(const InkStroke& stroke, const SnapSettings& settings);

} // namespace penshape::snap
