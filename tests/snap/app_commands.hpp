#pragma once
// Running the real apps from the snap tests: whether a program is installed, a command under
// Xvfb when there is no display, and comparing rendered regions.
#include <cstdlib>
#include <string>

#include "png_pixels.hpp"
#include "run_command.hpp"

namespace penshape::test {

inline bool have(const std::string& program) {
  return run_command("command -v " + program + " >/dev/null 2>&1").exit_code == 0;
}

// The apps need a display for GTK; without one they run under Xvfb.
inline std::string with_display(const std::string& cmd) {
  const char* display = std::getenv("DISPLAY");
  if (display != nullptr && *display != '\0') return cmd;
  return "xvfb-run -a " + cmd;
}

// Whether the two pictures agree (darkness within 8 of 255) on the box [x0, x1) x [y0, y1).
inline bool same_region(const Pixels& a, const Pixels& b, int x0, int y0, int x1, int y1) {
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      if (std::abs(a.ink(x, y) - b.ink(x, y)) > 8) return false;
    }
  }
  return true;
}

} // namespace penshape::test
