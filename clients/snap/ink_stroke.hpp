#pragma once
// A stroke as the snap library reads it from a drawing, whatever the format: where it is (for
// messages and --json), its pen path in page coordinates, the pen radius at each point and the
// style that decides what it may be grouped with.
#include <string>
#include <vector>

#include "penshape/core/recognize.hpp" // StrokePoint

namespace penshape::snap {

struct InkStroke {
  std::string where;               // "path#pencil3 (line 4)" or "page 1 layer 2 stroke 4 (...)"
  std::string locator;             // stable name for --json: the id, else an XPath-like path
  std::vector<StrokePoint> points; // drawing order; t is the index (documents keep no times)
  std::vector<double> radii;       // pen radius at each point, page units (same size)
  std::string style;               // tool, colour, markers: only equal styles are grouped
};

// Coordinates and pen widths beyond this (page units), or not finite, are not a drawing the
// recognizer can certify: such a stroke is left as drawn, with a warning.
inline constexpr double kMaxCoordinate = 1e6;

// Whether every point is finite and within kMaxCoordinate.
bool coordinates_in_range(const std::vector<StrokePoint>& points);

} // namespace penshape::snap
