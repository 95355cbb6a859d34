#pragma once
// Reads a gesture in the $1 Unistroke data set's format (../shared/data/strokes/dollar1, or the
// project's generated strokes written the same way): integer pixel points with millisecond times.
// Tests use these hand-drawn strokes as pen input.
#include <cstdint>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "generated_files.hpp"
#include "test_data.hpp"

namespace penshape::testing {

struct DollarPoint {
  int x = 0;
  int y = 0;
  std::int64_t t_ms = 0;
};

inline std::vector<DollarPoint> read_dollar_gesture(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  static const std::regex point(R"re(<Point X="(-?\d+)" Y="(-?\d+)" T="(\d+)")re");
  std::vector<DollarPoint> out;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), point); it != std::sregex_iterator();
       ++it) {
    out.push_back({std::stoi((*it)[1]), std::stoi((*it)[2]), std::stoll((*it)[3])});
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
