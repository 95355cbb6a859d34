#pragma once
// A stroke as the snap library reads it from a drawing, whatever the format: where it is (for
// messages and --json), its pen path in page coordinates and the pen radius at each point.
#include <string>
#include <vector>

#include "penshape/core/recognize.hpp" // StrokePoint

namespace penshape::snap {

struct InkStroke {
  std::string where;               // "path#pencil3" or "page 1 layer 2 stroke 4"
  std::vector<StrokePoint> points; // drawing order; t is the index (documents keep no times)
  std::vector<double> radii;       // pen radius at each point, page units (same size)
};

} // namespace penshape::snap
