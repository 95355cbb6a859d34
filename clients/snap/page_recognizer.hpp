#pragma once
// Recognizing the strokes of one page in drawing order: the single step of `penshape snap` that
// decides which strokes (or groups of strokes) become which clean shapes. Document order is the
// drawing order; with grouping (the default), strokes that together make one shape (a rectangle
// drawn side by side, an arrow's shaft and head) are recognized together as the core's
// StrokeGrouper does (group_recognize.hpp), certified on the union of their inks.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "ink_stroke.hpp"
#include "penshape/core/recognize.hpp"

namespace penshape::snap {

struct SnapSettings {
  double pen_radius = 0.0;   // page units; <= 0: each stroke's own (median) radius
  double tolerance = 0.0;    // page units; <= 0: the recognizer's rule (recognize.hpp)
  bool group = true;         // may strokes be grouped into one shape
  bool snap_writing = false; // snap writing strokes too (default: left as drawn, page_intent.hpp)
};

// One answer: the strokes it covers (indices into the page, ascending) and their recognition.
struct StrokeSnap {
  std::vector<std::size_t> strokes;
  Recognition recognition;       // in page units
  std::vector<std::string> tidy; // tidy-up constraints applied ("axis", "right_angles", ...)
};

// A whole page's answers, every stroke in exactly one of them: in-process
// (recognize_page_in_process) or through penshaped (daemon_recognizer.hpp).
using PageRecognizer =
    std::function<std::vector<StrokeSnap>(const std::vector<InkStroke>&, const SnapSettings&)>;

// The core in this process. Without grouping each stroke is recognized alone on its ink polygon
// (Certificate::method "ink"); with it, by a StrokeGrouper fed the strokes in document order.
// Throws SnapInputError naming the stroke the recognizer refuses.
std::vector<StrokeSnap> recognize_page_in_process(const std::vector<InkStroke>& page,
                                                  const SnapSettings& settings);

// The pen radius the clean shape is drawn with: the settings' radius, else the median of the
// stroke's radii.
double clean_pen_radius(const InkStroke& stroke, const SnapSettings& settings);

// The stroke's samples with times that place it `start` seconds into the page (documents keep
// no times: a stroke is taken as drawn right after the one before it).
std::vector<StrokePoint> timed_samples(const InkStroke& stroke, double start);

} // namespace penshape::snap
