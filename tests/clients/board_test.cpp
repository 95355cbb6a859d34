// The drawing board under Xvfb: a scripted hand-drawn rectangle (the $1 data set), the daemon's
// answer, and screenshots whose pixels must show the snapped shape, then, after undo, the raw
// stroke again.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "child_process.hpp"
#include "dollar_stroke.hpp"
#include "test_daemon.hpp"

namespace penshape::testing {
namespace {

// The board's colours and scale (clients/board/board_view.hpp, daemon_link.hpp).
struct Rgb {
  int r, g, b;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};
constexpr Rgb kWhite{255, 255, 255};
constexpr Rgb kRawInk{110, 70, 170};
constexpr Rgb kShapeInk{200, 30, 30};
constexpr double kPixelsPerMm = 4.0;

struct Image {
  int width = 0;
  int height = 0;
  std::vector<Rgb> pixels;
  [[nodiscard]] Rgb at(int x, int y) const {
    return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(x)];
  }
  [[nodiscard]] std::size_t count(Rgb c) const {
    return static_cast<std::size_t>(std::count(pixels.begin(), pixels.end(), c));
  }
};

// A 24-bit uncompressed BMP, as SDL_SaveBMP writes it.
Image read_bmp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string d((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto u32 = [&](std::size_t at) {
    return static_cast<std::uint32_t>(static_cast<unsigned char>(d.at(at))) |
           static_cast<std::uint32_t>(static_cast<unsigned char>(d.at(at + 1))) << 8U |
           static_cast<std::uint32_t>(static_cast<unsigned char>(d.at(at + 2))) << 16U |
           static_cast<std::uint32_t>(static_cast<unsigned char>(d.at(at + 3))) << 24U;
  };
  Image img;
  if (d.size() < 54 || d[0] != 'B' || d[1] != 'M') return img;
  const std::size_t offset = u32(10);
  img.width = static_cast<int>(u32(18));
  const auto h = static_cast<std::int32_t>(u32(22));
  img.height = std::abs(h);
  if ((u32(28) & 0xffffU) != 24) return {};
  const std::size_t stride = (static_cast<std::size_t>(img.width) * 3 + 3) / 4 * 4;
  for (int y = 0; y < img.height; ++y) {
    const std::size_t row =
        offset + stride * static_cast<std::size_t>(h > 0 ? img.height - 1 - y : y);
    for (int x = 0; x < img.width; ++x) {
      const std::size_t p = row + static_cast<std::size_t>(x) * 3;
      img.pixels.push_back({static_cast<unsigned char>(d.at(p + 2)),
                            static_cast<unsigned char>(d.at(p + 1)),
                            static_cast<unsigned char>(d.at(p))});
    }
  }
  return img;
}

std::optional<std::string> find_program(const std::string& name) {
  for (const char* dir : {"/usr/bin", "/usr/local/bin", "/bin"}) {
    const std::string path = std::string(dir) + "/" + name;
    if (::access(path.c_str(), X_OK) == 0) return path;
  }
  return std::nullopt;
}

// An X server of our own on a free display number.
class Xvfb {
 public:
  explicit Xvfb(const std::string& program)
      : process_({program, "-displayfd", "1", "-screen", "0", "1024x768x24", "-nolisten", "tcp"}) {
    const std::regex number(R"((^|\n)(\d+)\n)");
    for (int i = 0; i < 100 && display_.empty(); ++i) {
      process_.wait_for_output("\n", std::chrono::seconds(1));
      std::smatch m;
      const std::string out = process_.output();
      if (std::regex_search(out, m, number)) {
        display_ = ":"; // appended: g++ 12 warns falsely (-Wrestrict) on ":" + string
        display_ += m[2].str();
      }
    }
  }
  ~Xvfb() {
    process_.signal(SIGTERM);
    process_.wait();
  }
  [[nodiscard]] const std::string& display() const { return display_; }
  std::string output() { return process_.output(); }

 private:
  ChildProcess process_;
  std::string display_;
};

struct ScriptedStroke {
  std::vector<std::pair<int, int>> points; // window pixels
  std::string script_text;
};

// The $1 rectangle scaled into the window's middle (keeping its aspect), as a board script that
// draws it, waits for the daemon, takes a screenshot, undoes, takes another, and quits.
ScriptedStroke rectangle_script(const std::string& shot1, const std::string& shot2,
                                const std::string& prelude) {
  const auto gesture = read_dollar_gesture(dollar_rectangle_path());
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -(1 << 30), y1 = -(1 << 30);
  for (const auto& p : gesture) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  const double scale = std::min(440.0 / (x1 - x0), 360.0 / (y1 - y0));
  ScriptedStroke s;
  std::ostringstream script;
  script << prelude;
  for (std::size_t i = 0; i < gesture.size(); ++i) {
    const int x = 180 + static_cast<int>(std::lround((gesture[i].x - x0) * scale));
    const int y = 120 + static_cast<int>(std::lround((gesture[i].y - y0) * scale));
    s.points.emplace_back(x, y);
    script << (i == 0 ? "down " : "move ") << x << " " << y << "\n";
  }
  script << "up " << s.points.back().first << " " << s.points.back().second << "\n";
  script << "wait-answers 30\nscreenshot " << shot1 << "\nkey u\nscreenshot " << shot2
         << "\nquit\n";
  s.script_text = script.str();
  return s;
}

std::filesystem::path temp_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("penshape-board-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Every pixel on the closed polygon's edges (sampled every 2 px) has the shape's colour.
void expect_edges_drawn(const Image& img, const std::vector<std::pair<double, double>>& corners) {
  std::size_t checked = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const auto [ax, ay] = corners[i];
    const auto [bx, by] = corners[(i + 1) % corners.size()];
    const double len = std::hypot(bx - ax, by - ay);
    for (double t = 0; t <= len; t += 2) {
      const int x = static_cast<int>(std::lround(ax + (bx - ax) * t / len));
      const int y = static_cast<int>(std::lround(ay + (by - ay) * t / len));
      ASSERT_TRUE(x >= 0 && y >= 0 && x < img.width && y < img.height);
      const Rgb c = img.at(x, y);
      EXPECT_EQ(c, kShapeInk) << "edge " << i << " at (" << x << ", " << y << "): " << c.r << ","
                              << c.g << "," << c.b;
      ++checked;
    }
  }
  EXPECT_GT(checked, 400U);
}

// In sanitizer builds: SDL2's X11 and D-Bus backends keep allocations until exit in libraries
// it loads and unloads itself, which LeakSanitizer reports without a module name to suppress.
// Leak checking stays on for the board's own code in clients_board_core_test.
std::string board_asan_options() {
  const char* current = std::getenv("ASAN_OPTIONS");
  return std::string(current != nullptr ? current : "") + ":detect_leaks=0";
}

struct BoardRun {
  int exit_code = 0;
  std::string output;
  Image snapped;
  Image undone;
  ScriptedStroke stroke;
};

BoardRun run_board(const std::string& display, const std::string& address, const std::string& tag,
                   const std::string& prelude = "") {
  const auto dir = temp_dir(tag);
  BoardRun run;
  run.stroke =
      rectangle_script((dir / "snapped.bmp").string(), (dir / "undone.bmp").string(), prelude);
  std::ofstream(dir / "script.txt") << run.stroke.script_text;
  auto [code, out] = run_program(
      {PENSHAPE_BOARD, "--address", address, "--script", (dir / "script.txt").string()},
      {{"DISPLAY", display}, {"SDL_VIDEODRIVER", "x11"}, {"ASAN_OPTIONS", board_asan_options()}});
  run.exit_code = code;
  run.output = out;
  run.snapped = read_bmp((dir / "snapped.bmp").string());
  run.undone = read_bmp((dir / "undone.bmp").string());
  return run;
}

void expect_raw_stroke(const BoardRun& run) {
  // After undo: no shape left, and the pen's ink passes through every scripted point.
  const Image& img = run.undone;
  ASSERT_EQ(img.width, 800) << run.output;
  EXPECT_EQ(img.count(kShapeInk), 0U);
  for (const auto& [x, y] : run.stroke.points) EXPECT_EQ(img.at(x, y), kRawInk) << x << "," << y;
}

class Board : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto xvfb = find_program("Xvfb");
    if (!xvfb) GTEST_SKIP() << "Xvfb is not installed (scripts/setup.sh installs the xvfb package)";
    xvfb_ = std::make_unique<Xvfb>(*xvfb);
    ASSERT_FALSE(xvfb_->display().empty()) << "Xvfb did not start: " << xvfb_->output();
  }
  std::unique_ptr<Xvfb> xvfb_;
};

TEST_F(Board, ScriptedRectangleSnapsToTheDaemonsSquareAndUndoRestoresTheStroke) {
  TestDaemon daemon("board");
  // Before drawing: a wider pen (+, x1.25) and a looser tolerance (], x1.25, twice).
  const BoardRun run =
      run_board(xvfb_->display(), daemon.address, "double", "key =\nkey ]\nkey ]\n");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("stroke 1 is a square"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("undo: unsnapped"), std::string::npos) << run.output;
  // The daemon analysed the stroke with the board's adjusted settings (from 1 mm and 0.5).
  EXPECT_EQ(daemon.analyzer->calls.load(), 1);
  EXPECT_DOUBLE_EQ(daemon.analyzer->last_settings.pen_radius_mm, 1.25);
  EXPECT_DOUBLE_EQ(daemon.analyzer->last_settings.tolerance_fraction, 0.5 * 1.25 * 1.25);

  // The square the test double answers, computed here from the scripted points (window pixels
  // → mm at 4 px/mm → the square → pixels).
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (const auto& [x, y] : run.stroke.points) {
    x0 = std::min(x0, x / kPixelsPerMm), x1 = std::max(x1, x / kPixelsPerMm);
    y0 = std::min(y0, y / kPixelsPerMm), y1 = std::max(y1, y / kPixelsPerMm);
  }
  const double cx = (x0 + x1) / 2 * kPixelsPerMm, cy = (y0 + y1) / 2 * kPixelsPerMm;
  const double h = ((x1 - x0) + (y1 - y0)) / 4 * kPixelsPerMm;
  const Image& img = run.snapped;
  ASSERT_EQ(img.width, 800) << run.output;
  ASSERT_EQ(img.height, 600);
  expect_edges_drawn(img, {{cx - h, cy - h}, {cx + h, cy - h}, {cx + h, cy + h}, {cx - h, cy + h}});
  // Inside the square: paper.
  EXPECT_EQ(img.at(static_cast<int>(cx), static_cast<int>(cy)), kWhite);
  // The snapped stroke replaces the raw ink (drawn faintly underneath, not in the ink colour).
  EXPECT_EQ(img.count(kRawInk), 0U);
  expect_raw_stroke(run);
}

// Against the real penshaped: meaningful once the recognizer is merged into the daemon; until
// then the daemon says it has no stroke analyzer and the shape part is skipped.
TEST_F(Board, RealDaemonSnapsTheHandDrawnRectangle) {
  // The generated rectangles stay freeform on the board's path (its pen radius at the board's
  // scale; the CLI names them rectangles): a finding reported with issue 28, so this check runs
  // on the real $1 rectangle.
  PENSHAPE_SHARED_OR_SKIP(real, "strokes/dollar1/s02/slow/rectangle01.xml");
  const std::string address = unique_test_address("board-real");
  ChildProcess daemon({PENSHAPED, "--listen", address});
  ASSERT_TRUE(daemon.wait_for_output("listening on")) << daemon.output();
  const BoardRun run = run_board(xvfb_->display(), address, "real");
  daemon.signal(SIGTERM);
  EXPECT_EQ(daemon.wait(), 0) << daemon.output();
  ASSERT_EQ(run.exit_code, 0) << run.output;
  if (run.output.find("not analysed: this build has no stroke analyzer") != std::string::npos ||
      run.output.find("stroke 1: the daemon sent no shape (no recognizer)") != std::string::npos) {
    // The board still showed the raw stroke, and undo removed nothing that was not there.
    const Image& img = run.snapped;
    ASSERT_EQ(img.width, 800);
    for (const auto& [x, y] : run.stroke.points) EXPECT_EQ(img.at(x, y), kRawInk);
    GTEST_SKIP() << "penshaped has no recognizer yet (recognizer branch not merged): the board "
                    "drew the raw stroke; the snapped-shape check runs once it is. Board said:\n"
                 << run.output;
  }
  // The recognizer's answer: a rectangle or square, whose vertices the board prints in pixels.
  const std::regex answer(
      R"(stroke 1 is a (square|rectangle), vertices px((?: \(-?[0-9.]+,-?[0-9.]+\))+))");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(run.output, m, answer)) << run.output;
  const std::regex vertex(R"(\((-?[0-9.]+),(-?[0-9.]+)\))");
  const std::string list = m[2].str();
  std::vector<std::pair<double, double>> corners;
  for (auto it = std::sregex_iterator(list.begin(), list.end(), vertex);
       it != std::sregex_iterator(); ++it) {
    corners.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
  }
  ASSERT_EQ(corners.size(), 4U) << run.output;
  // The snapped rectangle is close to the drawn one: its corners near the gesture's box.
  expect_edges_drawn(run.snapped, corners);
  expect_raw_stroke(run);
}

// Hold to snap on the board, against the real penshaped (snap_trigger both, the default): the $1
// rectangle is drawn, the pen rests at its end (the board repeats its position, as a tablet does),
// and the daemon's HOLD snap shows while the pen is still down; the pen then drags the corner out
// and lifts, and the final shape is committed. Screenshots of both moments.
TEST_F(Board, HoldSnapsWhileThePenIsDownThenFollowsAndCommitsAtPenUp) {
  const std::string address = unique_test_address("board-hold");
  ChildProcess daemon({PENSHAPED, "--listen", address});
  ASSERT_TRUE(daemon.wait_for_output("listening on")) << daemon.output();
  const auto dir = temp_dir("hold");
  const std::string held = (dir / "held.bmp").string();
  const std::string released = (dir / "released.bmp").string();
  ScriptedStroke stroke = rectangle_script("unused", "unused", "");
  // The drawn rectangle without its "up" and what follows it: hold, drag, lift.
  std::string script = stroke.script_text.substr(0, stroke.script_text.find("up "));
  const auto [ex, ey] = stroke.points.back();
  script += "hold 900\nwait-held 20\nscreenshot " + held + "\n";
  for (int i = 1; i <= 10; ++i) {
    script += "move " + std::to_string(ex - 4 * i) + " " + std::to_string(ey - 3 * i) + "\n";
  }
  script += "hold 50\nup " + std::to_string(ex - 40) + " " + std::to_string(ey - 30) +
            "\nwait-answers 30\nscreenshot " + released + "\nquit\n";
  std::ofstream(dir / "script.txt") << script;
  auto [code, out] =
      run_program({PENSHAPE_BOARD, "--address", address, "--script", (dir / "script.txt").string()},
                  {{"DISPLAY", xvfb_->display()},
                   {"SDL_VIDEODRIVER", "x11"},
                   {"ASAN_OPTIONS", board_asan_options()}});
  daemon.signal(SIGTERM);
  EXPECT_EQ(daemon.wait(), 0) << daemon.output();
  ASSERT_EQ(code, 0) << out;
  EXPECT_NE(out.find("stroke 1 held: "), std::string::npos) << out;
  EXPECT_NE(out.find("stroke 1 is a "), std::string::npos) << out;
  // While the pen was down: the held shape drawn in the shape's colour, over the faint ink.
  const Image at_hold = read_bmp(held);
  ASSERT_EQ(at_hold.width, 800) << out;
  EXPECT_GT(at_hold.count(kShapeInk), 1000U);
  EXPECT_EQ(at_hold.count(kRawInk), 0U) << "the held shape replaces the raw ink";
  // After pen-up: the committed shape, dragged out: it reaches beyond the drawn rectangle's
  // corner where the pen lifted.
  const Image at_release = read_bmp(released);
  ASSERT_EQ(at_release.width, 800) << out;
  EXPECT_GT(at_release.count(kShapeInk), 1000U);
  EXPECT_EQ(at_release.count(kRawInk), 0U);
  std::size_t beyond = 0;
  for (int y = 0; y < at_release.height; ++y) {
    for (int x = 0; x < at_release.width; ++x) {
      if (at_release.at(x, y) == kShapeInk && x < ex - 20 && y < ey - 15) ++beyond;
    }
  }
  EXPECT_GT(beyond, 0U) << "the drag moved the shape";
}

TEST(BoardCli, RefusesBadUsageAndAMissingDaemon) {
  auto [code, out] = run_program({PENSHAPE_BOARD, "--radius", "0"});
  EXPECT_EQ(code, 2) << out;
  EXPECT_NE(out.find("--radius must be in"), std::string::npos) << out;
  std::tie(code, out) = run_program({PENSHAPE_BOARD, "--address", unique_test_address("none")});
  EXPECT_EQ(code, 1) << out;
  EXPECT_NE(out.find("penshaped is not running at"), std::string::npos) << out;
  const auto dir = temp_dir("bad-script");
  std::ofstream(dir / "bad.txt") << "down 1 2\nfly 3 4\n";
  std::tie(code, out) = run_program({PENSHAPE_BOARD, "--script", (dir / "bad.txt").string()});
  EXPECT_EQ(code, 2) << out;
  EXPECT_NE(out.find("bad.txt:2: unknown command 'fly'"), std::string::npos) << out;
  std::tie(code, out) = run_program({PENSHAPE_BOARD, "--help"});
  EXPECT_EQ(code, 0);
  EXPECT_NE(out.find("usage: penshape-board"), std::string::npos);
}

} // namespace
} // namespace penshape::testing
