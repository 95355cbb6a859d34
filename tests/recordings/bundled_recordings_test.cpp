// Every bundled recording (recordings/*.hidrec) replays through the drivers' decode path into
// exactly the strokes its .expected file lists, and each stroke is recognized as one of the
// classes listed for it. (The daemon's end-to-end replay test runs the same files over gRPC.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "penshape/core/recognize.hpp"
#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/replay.hpp"

namespace penshape {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> expected_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != '#') out.push_back(line);
  }
  return out;
}

bool class_accepted(const std::string& accepted, const std::string& got) {
  if (accepted == "*") return true;
  std::stringstream ss(accepted);
  for (std::string c; std::getline(ss, c, '|');) {
    if (c == got) return true;
  }
  return false;
}

TEST(BundledRecordings, ReplayIntoTheExpectedStrokesAndShapes) {
  const fs::path dir = fs::path(PENSHAPE_SOURCE_DIR) / "recordings";
  std::size_t recordings = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".hidrec") continue;
    ++recordings;
    fs::path expected_path = entry.path();
    expected_path.replace_extension(".expected");
    ASSERT_TRUE(fs::exists(expected_path)) << expected_path;
    const auto expected = expected_lines(expected_path);

    const drivers::Recording rec = drivers::load_recording_file(entry.path());
    const drivers::ReplayResult replayed =
        drivers::replay(rec, drivers::ReplaySpeed::kAsFastAsPossible);
    ASSERT_EQ(replayed.strokes.size(), expected.size()) << entry.path();
    const double rx = replayed.tablet.x_resolution > 0 ? replayed.tablet.x_resolution : 1.0;
    const double ry = replayed.tablet.y_resolution > 0 ? replayed.tablet.y_resolution : 1.0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      std::vector<StrokePoint> pts;
      for (const PenSample& s : replayed.strokes[i].samples) {
        if (s.tip) pts.push_back({s.x / rx, s.y / ry, static_cast<double>(s.time_us) * 1e-6});
      }
      if (pts.size() < 2) {
        EXPECT_EQ(expected[i], "*") << entry.path() << " stroke " << i;
        continue;
      }
      const Recognition r = recognize(pts);
      EXPECT_TRUE(class_accepted(expected[i], to_string(r.shape)))
          << entry.path().filename() << " stroke " << i << ": got " << to_string(r.shape)
          << ", expected " << expected[i];
    }
  }
  EXPECT_GE(recordings, 2U);
}

} // namespace
} // namespace penshape
