#pragma once
// Reads a gesture in the $1 Unistroke data set's format (../shared/data/strokes/dollar1, or the
// project's generated strokes written the same way): integer pixel points with millisecond times.
// Tests use these hand-drawn strokes as pen input.
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "dollar_xml.hpp"
#include "generated_files.hpp"
#include "test_data.hpp"

namespace penshape::testing {

struct DollarPoint {
  int x = 0;
  int y = 0;
  std::int64_t t_ms = 0;
};

inline std::vector<DollarPoint> read_dollar_gesture(const std::string& path) {
  std::vector<DollarPoint> out;
  for (const StrokePoint& p : dollar::read_dollar_xml(path).points) {
    out.push_back({static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y)),
                   std::llround(p.t * 1000.0)});
  }
  if (out.empty()) throw std::runtime_error(path + ": no <Point> elements");
  return out;
}

// A hand-drawn rectangle: the real one of the $1 logs (subject 2, slow) when the shared corpus
// is present, else one made by the stroke generator (tests/support/gen), as a $1 file.
inline std::string dollar_rectangle_path() {
  if (const auto real = test::shared_path("strokes/dollar1/s02/slow/rectangle01.xml")) {
    return real->string();
  }
  return stroke_file("rectangle", 2);
}

} // namespace penshape::testing
