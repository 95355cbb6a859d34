#pragma once
// Strokes for the hold-to-snap tests, as a hand would draw them (mm, seconds), with a hold, a
// tremor or a drag appended; written as JSON lines and turned into a tablet recording by the real
// `penshape synthesize-recording` (so the daemon reads them as a tablet's reports).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace penshape::daemon_test {

struct TimedPoint {
  double x = 0;
  double y = 0;
  double t = 0; // seconds
};
using TimedPath = std::vector<TimedPoint>;

// Through `corners` at `speed` mm/s, a point every 2 ms, with a small wobble across the way.
inline TimedPath drawn_through(const std::vector<std::pair<double, double>>& corners,
                               double speed) {
  TimedPath out{{corners[0].first, corners[0].second, 0}};
  for (std::size_t k = 1; k < corners.size(); ++k) {
    const auto [ax, ay] = corners[k - 1];
    const auto [bx, by] = corners[k];
    const double len = std::hypot(bx - ax, by - ay);
    const int n = std::max(2, static_cast<int>(len / speed / 0.002));
    for (int i = 1; i <= n; ++i) {
      const double f = static_cast<double>(i) / n;
      const double w = 0.2 * std::sin(7.0 * std::numbers::pi * f);
      out.push_back({ax + f * (bx - ax) - w * (by - ay) / len,
                     ay + f * (by - ay) + w * (bx - ax) / len, out.back().t + 0.002});
    }
  }
  return out;
}

// A circle of radius r around (0, 0) from angle 0, 1.05 turns in `seconds`, slightly wobbly.
inline TimedPath drawn_circle(double r, double seconds) {
  TimedPath out;
  const int n = static_cast<int>(seconds / 0.002);
  for (int i = 0; i <= n; ++i) {
    const double a = 2.1 * std::numbers::pi * i / n;
    const double rr = r + 0.25 * std::sin(5 * a);
    out.push_back({rr * std::cos(a), rr * std::sin(a), 0.002 * i});
  }
  out.push_back({r, 0, out.back().t + 0.05}); // back to where it began
  return out;
}

// The pen rests where it is for `seconds`, trembling by up to `tremor` mm.
inline void then_hold(TimedPath& path, double seconds, double tremor) {
  const TimedPoint rest = path.back();
  for (int i = 1; i * 0.005 <= seconds; ++i) {
    const double a = 2.4 * i;
    path.push_back(
        {rest.x + tremor * std::cos(a), rest.y + tremor * std::sin(a), rest.t + 0.005 * i});
  }
}

// The pen moves on by (dx, dy) in `seconds`, straight.
inline void then_move(TimedPath& path, double dx, double dy, double seconds) {
  const TimedPoint from = path.back();
  const int n = static_cast<int>(seconds / 0.002);
  for (int i = 1; i <= n; ++i) {
    const double f = static_cast<double>(i) / n;
    path.push_back({from.x + f * dx, from.y + f * dy, from.t + 0.002 * i});
  }
}

// JSON lines, one stroke a line, each stroke starting after the previous one.
inline void write_strokes(const std::filesystem::path& file,
                          const std::vector<TimedPath>& strokes) {
  std::ofstream out(file);
  out.precision(10);
  double t0 = 0;
  for (const TimedPath& path : strokes) {
    out << "{\"points\": [";
    for (std::size_t i = 0; i < path.size(); ++i) {
      out << (i ? ", " : "") << '[' << path[i].x << ", " << path[i].y << ", " << t0 + path[i].t
          << ']';
    }
    out << "]}\n";
    t0 += path.back().t + 1.0;
  }
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

// `penshape synthesize-recording` of the strokes as the reports of the tablet in the generated
// default recording, at `rate_hz`, `mm_per_unit` millimetres per stroke unit, four strokes a row.
inline void synthesize(const std::filesystem::path& strokes, const std::filesystem::path& out,
                       int rate_hz, double mm_per_unit) {
  const std::string command =
      std::string("'") + PENSHAPE_BINARY_DIR + "/clients/penshape' synthesize-recording" +
      " --descriptor '" + PENSHAPE_SOURCE_DIR +
      "/recordings/generated-shapes.hidrec' --vid 1209 --pid 7e57 --columns 4" + " --rate " +
      std::to_string(rate_hz) + " --mm-per-unit " + std::to_string(mm_per_unit) + " --out '" +
      out.string() + "' '" + strokes.string() + "' > /dev/null";
  if (std::system(command.c_str()) != 0) throw std::runtime_error("failed: " + command);
}

} // namespace penshape::daemon_test
