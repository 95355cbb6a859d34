// The real apps on snap's files: the Inkscape extension run as Inkscape runs it (its script with
// Inkscape's inkex, on the current layer and on a selection), the real `inkscape` exporting the
// result to PNG, and the real `xournalpp --create-pdf` with `pdftoppm` for .xopp. The pixels must
// show the clean shape and no longer the raw stroke; other content must render as before. Each
// test skips, saying why, when its app is absent (scripts/setup.sh installs them; CI has them).
// The files stay in the build folder (tests/snap/apps/) as the README's pictures.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "app_commands.hpp"
#include "snap_checks.hpp"
#include "snap_fixtures.hpp"
#include "test_data.hpp"

namespace penshape::test {
namespace {

namespace fs = std::filesystem;
const std::string kCli = PENSHAPE_CLI;
const std::string kExtension = std::string(PENSHAPE_SOURCE_DIR) + "/clients/inkscape";
const std::string kInkex = "/usr/share/inkscape/extensions";
constexpr unsigned kParse = pugi::parse_full | pugi::parse_ws_pcdata;

fs::path out_dir() {
  fs::path d = fs::path(PENSHAPE_BINARY_DIR) / "tests" / "snap" / "apps";
  fs::create_directories(d);
  return d;
}

std::string extension(const std::string& args) {
  return "cd " + kExtension + " && PYTHONPATH=" + kInkex + " PENSHAPE_CLI=" + kCli +
         " /usr/bin/python3 penshape_snap.py " + args + " 2>&1";
}

void skip_without_inkex(bool& skipped) {
  const auto r = run_command("PYTHONPATH=" + kInkex + " /usr/bin/python3 -c 'import inkex' 2>&1");
  skipped = r.exit_code != 0;
}

// Share of the points where the picture has ink (darkness above half).
double inked_share(const Pixels& px, const std::vector<PointD>& pts) {
  std::size_t n = 0;
  for (const PointD& p : pts) n += px.ink(p.x, p.y) > 128 ? 1 : 0;
  return pts.empty() ? 0 : static_cast<double>(n) / static_cast<double>(pts.size());
}

std::vector<PointD> circle_points(double cx, double cy, double r) {
  std::vector<PointD> out;
  out.reserve(90);
  for (int i = 0; i < 90; ++i)
    out.push_back({cx + r * std::cos(i * M_PI / 45), cy + r * std::sin(i * M_PI / 45)});
  return out;
}

// The raw stroke's points farther than `gap` from the clean circle: where only the raw ink was.
std::vector<PointD> raw_only(const std::vector<PointD>& raw, double cx, double cy, double r,
                             double gap) {
  std::vector<PointD> out;
  for (const PointD& p : raw) {
    if (std::abs(std::hypot(p.x - cx, p.y - cy) - r) > gap) out.push_back(p);
  }
  return out;
}

TEST(InkscapeExtension, SnapsTheCurrentLayerOrTheSelection) {
  bool skipped = false;
  skip_without_inkex(skipped);
  if (skipped) GTEST_SKIP() << "Inkscape's inkex (" << kInkex << ", python3-lxml) is not installed";
  const fs::path dir = out_dir();
  const Fixture f = inkscape_fixture();
  write_bytes(dir / "drawing.svg", f.text);
  // Nothing selected: the current layer (layer1, from the named view).
  const auto r = run_command(extension("--output=" + (dir / "drawing-snapped.svg").string() + " " +
                                       (dir / "drawing.svg").string()));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  pugi::xml_document in, out;
  ASSERT_TRUE(in.load_file((dir / "drawing.svg").c_str(), kParse));
  ASSERT_TRUE(out.load_file((dir / "drawing-snapped.svg").c_str(), kParse));
  EXPECT_STREQ(by_id(out, "pencil-circle").name(), "circle");
  EXPECT_STREQ(by_id(out, "pencil-rect").attribute("data-penshape-class").value(), "rectangle");
  EXPECT_STREQ(by_id(out, "callig-triangle").name(), "polygon");
  EXPECT_STREQ(by_id(out, "pencil-pigtail").name(), "path");
  EXPECT_STREQ(by_id(out, "notes-circle").name(), "path") << "the other layer is not touched";
  for (const char* id : {"label", "photo", "note"}) {
    EXPECT_STREQ(by_id(out, id).name(), by_id(in, id).name()) << id;
    EXPECT_STREQ(by_id(out, id).attribute("style").value(),
                 by_id(in, id).attribute("style").value());
  }
  // A selection (Inkscape passes --id): only that element.
  const auto s = run_command(
      extension("--id=notes-circle --output=" + (dir / "drawing-selection.svg").string() + " " +
                (dir / "drawing.svg").string()));
  ASSERT_EQ(s.exit_code, 0) << s.out;
  pugi::xml_document sel;
  ASSERT_TRUE(sel.load_file((dir / "drawing-selection.svg").c_str(), kParse));
  EXPECT_STREQ(by_id(sel, "notes-circle").attribute("data-penshape-class").value(),
               "circle"); // tidied: a near-circular ellipse
  EXPECT_STREQ(by_id(sel, "pencil-circle").name(), "path");
  // Options reach the CLI: a tolerance of 0.5 px certifies nothing (the message says so).
  const auto t = run_command(extension("--tolerance=0.5 --output=" + (dir / "tight.svg").string() +
                                       " " + (dir / "drawing.svg").string()));
  EXPECT_EQ(t.exit_code, 0) << t.out;
  EXPECT_NE(t.out.find("no stroke was certified"), std::string::npos) << t.out;
}

TEST(InkscapeExtension, SaysSoWhenNoPenshapeIsFound) {
  bool skipped = false;
  skip_without_inkex(skipped);
  if (skipped) GTEST_SKIP() << "Inkscape's inkex (" << kInkex << ") is not installed";
  const fs::path dir = out_dir();
  write_bytes(dir / "drawing.svg", inkscape_fixture().text);
  const auto r = run_command("cd " + kExtension +
                             " && HOME=/nonexistent XDG_RUNTIME_DIR=/nonexistent "
                             "PATH=/nonexistent PENSHAPE_CLI=/nonexistent PYTHONPATH=" +
                             kInkex + " /usr/bin/python3 penshape_snap.py --output=/dev/null " +
                             (dir / "drawing.svg").string() + " 2>&1");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.out.find("needs the penshape command, which was not found"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("penshaped is not running either"), std::string::npos) << r.out;
}

// The real Inkscape runs the installed extension by its id (the menu entry's action), on a
// selection and on the current layer, and saves the result.
TEST(InkscapeApp, RunsTheExtensionFromItsMenuAction) {
  if (!have("inkscape")) GTEST_SKIP() << "inkscape is not installed (scripts/setup.sh installs it)";
  if (!have("xvfb-run") && std::getenv("DISPLAY") == nullptr)
    GTEST_SKIP() << "no display and no xvfb-run";
  const fs::path dir = out_dir();
  const fs::path home = dir / "home", ext = home / ".config/inkscape/extensions";
  fs::create_directories(ext);
  for (const char* f : {"penshape_snap.inx", "penshape_snap.py"}) {
    fs::copy_file(kExtension + "/" + f, ext / f, fs::copy_options::overwrite_existing);
  }
  write_bytes(dir / "app.svg", inkscape_fixture().text);
  const auto run = [&](const std::string& select, const std::string& out) {
    return run_command(
        "HOME=" + home.string() + " PENSHAPE_CLI=" + kCli + " " +
        with_display("inkscape --with-gui --batch-process --actions=\"" + select +
                     "org.penshape.snap.noprefs;export-filename:" + (dir / out).string() +
                     ";export-do\" " + (dir / "app.svg").string()) +
        " 2>&1");
  };
  const auto listed = run_command("HOME=" + home.string() + " " +
                                  with_display("inkscape --action-list") + " 2>/dev/null");
  ASSERT_NE(listed.out.find("org.penshape.snap"), std::string::npos) << "extension not loaded";
  const auto sel = run("select-by-id:pencil-circle;", "app-selection.svg");
  ASSERT_EQ(sel.exit_code, 0) << sel.out;
  pugi::xml_document a;
  ASSERT_TRUE(a.load_file((dir / "app-selection.svg").c_str())) << sel.out;
  EXPECT_STREQ(by_id(a, "pencil-circle").name(), "circle");
  EXPECT_STREQ(by_id(a, "pencil-circle").attribute("data-penshape-class").value(), "circle");
  EXPECT_STREQ(by_id(a, "pencil-rect").name(), "path");
  const auto layer = run("", "app-layer.svg");
  ASSERT_EQ(layer.exit_code, 0) << layer.out;
  pugi::xml_document b;
  ASSERT_TRUE(b.load_file((dir / "app-layer.svg").c_str())) << layer.out;
  EXPECT_STREQ(by_id(b, "pencil-circle").name(), "circle");
  EXPECT_STREQ(by_id(b, "pencil-rect").attribute("data-penshape-class").value(), "rectangle");
  EXPECT_STREQ(by_id(b, "notes-circle").name(), "path") << "another layer";
}

TEST(InkscapeExport, ShowsTheCleanShapeAndNotTheRawStroke) {
  if (!have("inkscape")) GTEST_SKIP() << "inkscape is not installed (scripts/setup.sh installs it)";
  const fs::path dir = out_dir();
  const Fixture f = inkscape_fixture();
  write_bytes(dir / "export.svg", f.text);
  const auto snap = run_command(kCli + " snap --local " + (dir / "export.svg").string() + " " +
                                (dir / "export-snapped.svg").string() + " 2>&1");
  ASSERT_EQ(snap.exit_code, 0) << snap.out;
  for (const char* name : {"export", "export-snapped"}) {
    const auto r = run_command(with_display(
        "inkscape --export-type=png --export-area-page --export-width=800 --export-filename=" +
        (dir / (std::string(name) + ".png")).string() + " " +
        (dir / (std::string(name) + ".svg")).string() + " 2>&1"));
    ASSERT_EQ(r.exit_code, 0) << r.out;
  }
  const Pixels before = read_png((dir / "export.png").string());
  const Pixels after = read_png((dir / "export-snapped.png").string());
  ASSERT_EQ(after.width, 800);
  pugi::xml_document out;
  ASSERT_TRUE(out.load_file((dir / "export-snapped.svg").c_str()));
  const pugi::xml_node c = by_id(out, "pencil-circle");
  ASSERT_STREQ(c.name(), "circle");
  const double cx = c.attribute("cx").as_double(), cy = c.attribute("cy").as_double(),
               r = c.attribute("r").as_double();
  // The clean circle is drawn (8 px wide) ...
  EXPECT_GE(inked_share(after, circle_points(cx, cy, r)), 0.95);
  // ... and where only the raw stroke was (its centre farther than the pen's half width and a
  // pixel and a half from the circle), the picture was inked before and is blank now.
  const auto only_raw = raw_only(f.strokes[0].points, cx, cy, r, 4 + 1.5);
  ASSERT_GE(only_raw.size(), 5u) << "the raw stroke wanders off the circle somewhere";
  EXPECT_GE(inked_share(before, only_raw), 0.9);
  EXPECT_LE(inked_share(after, only_raw), 0.1);
  // The text, the image and the freeform stroke render as before.
  EXPECT_TRUE(same_region(before, after, 600, 280, 680, 360)) << "image";
  EXPECT_TRUE(same_region(before, after, 290, 270, 430, 305)) << "text";
  EXPECT_TRUE(same_region(before, after, 450, 50, 550, 150)) << "pigtail";
}

TEST(XournalExport, ShowsTheCleanShapeAndNotTheRawStroke) {
  if (!have("xournalpp"))
    GTEST_SKIP() << "xournalpp is not installed (scripts/setup.sh installs it)";
  if (!have("pdftoppm")) GTEST_SKIP() << "pdftoppm (poppler-utils) is not installed";
  const fs::path dir = out_dir();
  const Fixture f = xopp_fixture();
  write_bytes(dir / "notes.xopp", gzip_bytes(f.text));
  const auto snap = run_command(kCli + " snap --local --json " + (dir / "notes.xopp").string() +
                                " " + (dir / "notes-snapped.xopp").string() + " 2>/dev/null");
  ASSERT_EQ(snap.exit_code, 0) << snap.out;
  for (const char* name : {"notes", "notes-snapped"}) {
    const std::string stem = (dir / name).string();
    std::string to_pdf = "xournalpp --create-pdf=";
    to_pdf.append(stem).append(".pdf ").append(stem).append(".xopp");
    std::string command = with_display(to_pdf);
    command.append(" >/dev/null 2>&1 && pdftoppm -r 72 -png -singlefile ")
        .append(stem)
        .append(".pdf ")
        .append(stem)
        .append(" 2>&1");
    const auto r = run_command(command);
    ASSERT_EQ(r.exit_code, 0) << r.out;
  }
  const Pixels before = read_png((dir / "notes.png").string());
  const Pixels after = read_png((dir / "notes-snapped.png").string());
  ASSERT_EQ(after.width, 800);
  // The circle's centre and radius as --json printed them.
  const auto at = snap.out.find("\"class\":\"circle\"");
  ASSERT_NE(at, std::string::npos) << snap.out;
  const auto centre = snap.out.find("\"center\":[", at);
  const auto radius = snap.out.find("\"radius_x\":", at);
  const auto c = numbers_of(snap.out.substr(centre + 10, snap.out.find(']', centre) - centre - 10));
  const double r = std::stod(snap.out.substr(radius + 11));
  EXPECT_GE(inked_share(after, circle_points(c[0], c[1], r)), 0.95);
  const auto only_raw = raw_only(f.strokes[0].points, c[0], c[1], r, 5.67 / 2 + 1.5);
  ASSERT_GE(only_raw.size(), 3u);
  EXPECT_GE(inked_share(before, only_raw), 0.9);
  EXPECT_LE(inked_share(after, only_raw), 0.1);
  EXPECT_TRUE(same_region(before, after, 600, 300, 680, 380)) << "image";
  EXPECT_TRUE(same_region(before, after, 55, 280, 200, 305)) << "text";
  EXPECT_TRUE(same_region(before, after, 490, 70, 580, 160)) << "pigtail";
}

} // namespace
} // namespace penshape::test
