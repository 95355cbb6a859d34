#pragma once
// Generated test data (tests/support/gen) written as the files the CLI reads, in the build folder:
// what the CLI tests of a bare clone run on. Real files come from the shared corpus instead.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "polygon_gen.hpp"
#include "stroke_files.hpp"
#include "stroke_gen.hpp"

namespace penshape::testing {

// Written whole under a name of this process's own, then renamed into place: ctest runs each
// test in a process of its own, in parallel, and every process of a test program writes the same
// files as it starts; a file truncated in place could be read half-written by another test's CLI.
inline std::string write_generated(const std::string& name, const std::string& text) {
  std::string path = std::string(PENSHAPE_BINARY_DIR) + "/generated_" + name;
  const std::string own = path + ".part" + std::to_string(::getpid());
  {
    std::ofstream out(own, std::ios::binary);
    out << text;
    if (!out.flush()) throw std::runtime_error("cannot write " + own);
  }
  std::error_code error;
  std::filesystem::rename(own, path, error);
  if (error) throw std::runtime_error("cannot write " + path + ": " + error.message());
  return path;
}

// A YES case at r = 1, eps = 0.1: a convex hexagon offset by 1 (chords within 0.02).
inline std::string rounded_hexagon_file() {
  return write_generated("rounded_hexagon.txt", gen::rounded_convex(8, 6, 10.0, 1.0, 0.02).q.text);
}
// A NO case at r = 1, eps = 0.1: a 5 x 5 square (its corners are 0.41 r from any offset by r).
inline std::string square_file() {
  return write_generated("square5.txt", "# a 5 x 5 square\n0 0\n5 0\n5 5\n0 5\n");
}
// A coastline about 100 units across (like the authors' S).
inline std::string coast_file() {
  return write_generated("coast.txt", gen::country(12, 160, 50.0).text);
}
// One generated stroke of `kind` as a $1 gesture log.
inline std::string stroke_file(const std::string& kind, std::uint64_t seed) {
  gen::StrokeGenerator generator(seed);
  const gen::Drawing d = generator.draw(kind);
  const std::string name = kind + "01";
  return write_generated(name + "_" + std::to_string(seed) + ".xml",
                         gen::to_dollar_xml(d.strokes.front(), name, 1, gen::Speed::kMedium));
}

} // namespace penshape::testing
