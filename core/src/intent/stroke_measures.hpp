#pragma once
// What the writing/drawing decision measures on one stroke alone (in millimetres and seconds):
// its box, path length, turning, straightness and speed.
#include <limits>
#include <span>

#include "penshape/core/intent.hpp"

namespace penshape::intent {

struct Box {
  double x0 = std::numeric_limits<double>::infinity();
  double y0 = std::numeric_limits<double>::infinity();
  double x1 = -std::numeric_limits<double>::infinity();
  double y1 = -std::numeric_limits<double>::infinity();
  [[nodiscard]] double width() const { return x1 - x0; }
  [[nodiscard]] double height() const { return y1 - y0; }
  [[nodiscard]] double center_y() const { return 0.5 * (y0 + y1); }
};

struct StrokeMeasures {
  Box box;                 // mm
  double size = 0.0;       // max(width, height), mm
  double length = 0.0;     // path length, mm
  double turning = 0.0;    // total absolute turning, radians (on the thinned path)
  int reversals = 0;       // changes of turning direction (on the thinned path)
  double straightness = 1; // chord / length (1 for a dot)
  double closedness = 0;   // distance between the ends / size
  bool dot = true;         // one distinct point (or none)
  bool timed = false;      // times increase along the stroke
  double start_t = 0.0;    // s
  double end_t = 0.0;      // s
  double speed = 0.0;      // mm/s when timed
};

// Throws InvalidInput for a coordinate or time that is not finite.
StrokeMeasures measure_stroke(IntentStroke stroke, double mm_per_unit);

// The model's features of stroke `i` among `all` (the page's measures), its context within
// `window` strokes (intent_features.cpp).
IntentFeatures features_at(std::span<const StrokeMeasures> all, std::size_t i, std::size_t window);

} // namespace penshape::intent
