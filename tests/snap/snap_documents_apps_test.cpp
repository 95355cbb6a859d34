// The real apps on snap's outputs of project-made documents with what real files hold (issue
// #29): Xournal++ 1.1 (`xournalpp --create-pdf`, then `pdftoppm`) on a zip-packaged .xopp with
// pressure widths of -1 and 0, a tap dot, text and a freeform stroke, and on 200 pages; Inkscape
// (`inkscape --export-type=png`) on an SVG with a closed square, a stroke with an arrowhead marker
// drawn right to left, sides of different colours, variable-width calligraphy and text, and on
// 10,000 nested groups; and an arrow drawn head first, in both. Every output must open; the pixels
// of untouched parts must not change. Each test skips, saying why, when its app is absent. The
// files stay in the build folder (tests/snap/apps-documents/).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app_commands.hpp"
#include "snap_documents.hpp"
#include "snap_fixtures.hpp"
#include "test_data.hpp"

namespace penshape::test {
namespace {

namespace fs = std::filesystem;
using namespace docs;
const std::string kCli = PENSHAPE_CLI;

fs::path out_dir() {
  fs::path d = fs::path(PENSHAPE_BINARY_DIR) / "tests" / "snap" / "apps-documents";
  fs::create_directories(d);
  return d;
}

CommandResult snap(const fs::path& in, const fs::path& out) {
  return run_command(kCli + " snap --local --quiet " + in.string() + " " + out.string() + " 2>&1");
}

// Renders a .xopp to stem.png (72 dpi: one pixel per pt) through Xournal++'s PDF export.
CommandResult xournal_png(const std::string& stem) {
  return run_command(with_display("xournalpp --create-pdf=" + stem + ".pdf " + stem + ".xopp") +
                     " >/dev/null 2>&1 && pdftoppm -r 72 -png -singlefile " + stem + ".pdf " +
                     stem + " 2>&1");
}

// Renders an SVG of 400 user units wide to stem.png, one pixel per unit.
CommandResult inkscape_png(const std::string& stem) {
  return run_command(with_display("inkscape --export-type=png --export-area-page "
                                  "--export-width=400 --export-filename=" +
                                  stem + ".png " + stem + ".svg") +
                     " 2>&1");
}

// A document snapped and both versions rendered by an app: the pictures, or what failed.
struct BeforeAfter {
  std::string snap_output, failure;
  Pixels before, after;
};

// Snaps dir/stem+ext to dir/stem-snapped+ext and renders both with `render`.
BeforeAfter snap_and_render(const fs::path& dir, const std::string& stem, const std::string& ext,
                            CommandResult (*render)(const std::string&)) {
  BeforeAfter out;
  const auto r = snap(dir / (stem + ext), dir / (stem + "-snapped" + ext));
  out.snap_output = r.out;
  if (r.exit_code != 0) {
    out.failure = "snap exits " + std::to_string(r.exit_code) + ": " + r.out;
    return out;
  }
  for (const std::string& name : {stem, stem + "-snapped"}) {
    const auto png = render((dir / name).string());
    if (png.exit_code != 0) {
      out.failure = name + ext + " does not open in the app: " + png.out;
      return out;
    }
  }
  out.before = read_png((dir / (stem + ".png")).string());
  out.after = read_png((dir / (stem + "-snapped.png")).string());
  return out;
}

double inked_share(const Pixels& px, const std::vector<PointD>& pts) {
  std::size_t n = 0;
  for (const PointD& p : pts) n += px.ink(p.x, p.y) > 100 ? 1 : 0;
  return pts.empty() ? 0 : static_cast<double>(n) / static_cast<double>(pts.size());
}

// Pixels of the box that are clearly red (the marker's and the red sides' colour).
int red_pixels(const Pixels& px, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = std::max(0, y0); y < std::min(px.height, y1); ++y) {
    for (int x = std::max(0, x0); x < std::min(px.width, x1); ++x) {
      const std::uint8_t* p =
          &px.rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(px.width) +
                   static_cast<std::size_t>(x)) *
                  3];
      n += p[0] > 150 && p[1] < 90 && p[2] < 90 ? 1 : 0;
    }
  }
  return n;
}

std::string pressures(std::size_t points, const char* last) {
  std::string w = "2";
  for (std::size_t i = 0; i + 1 < points; ++i) w += " 2.1";
  return w + " " + last;
}

bool skip_without_xournal(std::string& why) {
  if (!have("xournalpp")) {
    why = "xournalpp is not installed (scripts/setup.sh installs it)";
  } else if (!have("pdftoppm")) {
    why = "pdftoppm (poppler-utils) is not installed";
  }
  return !why.empty();
}

TEST(XournalDocuments, ZipWithPressureAndDotsOpensAndKeepsTheRest) {
  std::string why;
  if (skip_without_xournal(why)) GTEST_SKIP() << why;
  const fs::path dir = out_dir();
  const auto a = wobbly_circle(90, 90, 60), b = wobbly_circle(90, 230, 40);
  std::vector<PointD> squiggle;
  for (int i = 0; i <= 60; ++i) squiggle.push_back({220 + 2.6 * i, 230 + 18 * std::sin(i * 0.35)});
  const std::string xml = xopp_document(
      {xopp_stroke(a, pressures(a.size() - 1, "-1")) + // 1.0.x: one per point, -1 last
       xopp_stroke(b, pressures(b.size() - 2, "0")) +  // 0 at pen lift
       xopp_stroke({{300, 40}, {300, 40}}, "3") +      // a tap: a dot
       xopp_stroke(squiggle, "2", "#0000ffff") +
       "<text font=\"Sans\" size=\"12\" x=\"250\" y=\"100\" color=\"#000000ff\">Hello</text>\n"});
  write_bytes(dir / "package.xopp", zip_package({{"mimetype", "application/xournal++"},
                                                 {"META-INF/version", "current=4\nmin=4\n"},
                                                 {"content.xml", xml},
                                                 {"attachments/notes.txt", "an attachment"}}));
  const BeforeAfter pictures = snap_and_render(dir, "package", ".xopp", xournal_png);
  ASSERT_EQ(pictures.failure, "");
  EXPECT_NE(pictures.snap_output.find("2 of 4 strokes snapped"), std::string::npos);
  const Pixels &before = pictures.before, &after = pictures.after;
  ASSERT_EQ(after.width, 400);
  EXPECT_GE(inked_share(after, wobbly_circle(90, 90, 60, 90)), 0.9);
  EXPECT_TRUE(same_region(before, after, 285, 25, 315, 55)) << "the dot";
  EXPECT_TRUE(same_region(before, after, 245, 95, 340, 125)) << "the text";
  EXPECT_TRUE(same_region(before, after, 210, 200, 390, 260)) << "the freeform stroke";
  EXPECT_EQ(zip_entries(read_file(dir / "package-snapped.xopp")).at("attachments/notes.txt"),
            "an attachment");
}

TEST(XournalDocuments, TwoHundredPagesOpen) {
  std::string why;
  if (skip_without_xournal(why)) GTEST_SKIP() << why;
  const fs::path dir = out_dir();
  std::vector<std::string> pages;
  pages.reserve(200);
  for (int p = 0; p < 200; ++p) {
    pages.push_back(xopp_stroke(wobbly_circle(100.0 + p % 7 * 20, 150, 50), "2") +
                    xopp_stroke(wobbly_line({250, 50}, {380, 50.0 + p % 5 * 40}), "2"));
  }
  write_bytes(dir / "pages.xopp", gzip_bytes(xopp_document(pages)));
  const auto r = snap(dir / "pages.xopp", dir / "pages-snapped.xopp");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("of 400 strokes snapped"), std::string::npos) << r.out;
  const std::string stem = (dir / "pages-snapped").string();
  const auto pdf =
      run_command(with_display("xournalpp --create-pdf=" + stem + ".pdf " + stem + ".xopp") +
                  " >/dev/null 2>&1 && pdfinfo " + stem + ".pdf 2>&1");
  ASSERT_EQ(pdf.exit_code, 0) << pdf.out;
  const auto pages_at = pdf.out.find("Pages:");
  ASSERT_NE(pages_at, std::string::npos) << pdf.out;
  EXPECT_EQ(std::stoi(pdf.out.substr(pages_at + 6)), 200) << pdf.out;
}

TEST(InkscapeDocuments, DrawersIntentionsRenderAndTheRestStays) {
  if (!have("inkscape")) GTEST_SKIP() << "inkscape is not installed (scripts/setup.sh installs it)";
  const fs::path dir = out_dir();
  std::string sides;
  const std::vector<std::pair<PointD, PointD>> box{{{200, 80}, {380, 80}},
                                                   {{380, 80}, {380, 180}},
                                                   {{380, 180}, {200, 180}},
                                                   {{200, 180}, {200, 80}}};
  for (std::size_t i = 0; i < box.size(); ++i) {
    sides += std::string("<polyline fill=\"none\" stroke-width=\"3\" stroke=\"") +
             (i % 2 == 1 ? "#ff0000" : "#000000") + "\" points=\"" +
             coordinates(wobbly_line(box[i].first, box[i].second), ",") + "\"/>\n";
  }
  std::vector<PointD> outline;
  const auto centre = wobbly_line({40, 240}, {200, 240}, 40);
  for (std::size_t i = 0; i < centre.size(); ++i) {
    outline.push_back({centre[i].x, centre[i].y - 1 - 0.2 * static_cast<double>(i)});
  }
  for (std::size_t i = centre.size(); i-- > 0;) {
    outline.push_back({centre[i].x, centre[i].y + 1 + 0.2 * static_cast<double>(i)});
  }
  write_bytes(
      dir / "intent.svg",
      svg_document("<path style=\"fill:none;stroke:#000;stroke-width:3\" d=\"M40 40 L140 40 "
                   "L140 140 L40 140 Z\"/>\n"
                   "<polyline fill=\"none\" stroke=\"#000\" stroke-width=\"2\" "
                   "marker-end=\"url(#arrow)\" points=\"" +
                   coordinates(wobbly_line({380, 30}, {200, 30}), ",") + "\"/>\n" + sides +
                   "<path style=\"fill:#000;stroke:none\" d=\"M " + coordinates(outline, ",") +
                   " Z\"/>\n<text x=\"250\" y=\"260\" font-size=\"16\">Hello</text>\n"));
  const BeforeAfter pictures = snap_and_render(dir, "intent", ".svg", inkscape_png);
  ASSERT_EQ(pictures.failure, "");
  const Pixels &before = pictures.before, &after = pictures.after;
  ASSERT_EQ(after.width, 400);
  // The square's closing side (x = 40) is drawn.
  std::vector<PointD> left;
  for (int y = 50; y <= 130; y += 5) left.push_back({40, static_cast<double>(y)});
  EXPECT_GE(inked_share(after, left), 0.9);
  // The arrowhead stays at the left end, where the stroke ended.
  EXPECT_GT(red_pixels(after, 190, 20, 215, 42), 5);
  EXPECT_EQ(red_pixels(after, 360, 20, 395, 42), 0);
  // The red sides stay red.
  EXPECT_GT(red_pixels(after, 372, 90, 388, 170), 20);
  EXPECT_GT(red_pixels(after, 192, 90, 208, 170), 20);
  EXPECT_EQ(red_pixels(after, 212, 72, 368, 88), 0) << "the black top side turned red";
  // Untouched: the calligraphy and the text.
  EXPECT_TRUE(same_region(before, after, 30, 220, 215, 275)) << "calligraphy";
  EXPECT_TRUE(same_region(before, after, 245, 240, 320, 270)) << "text";
}

// An arrow drawn head first (the barbs meeting at (100, 150), then the shaft to the tail at
// (300, 150)), both strokes with an arrowhead marker at their end: the snapped arrow opens in
// both apps with its head drawn where the drawer drew it, and in Inkscape the one path's marker
// sits at the tail, where the pen stopped, and nowhere near the head.
std::vector<std::vector<PointD>> head_first_arrow() {
  std::vector<PointD> head = wobbly_line({120, 135}, {100, 150}, 8);
  const auto barb = wobbly_line({100, 150}, {120, 165}, 8);
  head.insert(head.end(), barb.begin() + 1, barb.end());
  return {head, wobbly_line({100, 150}, {300, 150}, 24)};
}

// Points along the drawn head's barbs and the shaft.
std::vector<PointD> arrow_ink_points() {
  std::vector<PointD> out;
  for (int i = 2; i <= 8; ++i) {
    out.push_back({100 + 2.0 * i, 150 - 1.5 * i});
    out.push_back({100 + 2.0 * i, 150 + 1.5 * i});
  }
  for (int x = 140; x <= 280; x += 10) out.push_back({static_cast<double>(x), 150});
  return out;
}

TEST(InkscapeDocuments, ArrowDrawnHeadFirstPointsWhereItWasDrawn) {
  if (!have("inkscape")) GTEST_SKIP() << "inkscape is not installed (scripts/setup.sh installs it)";
  const fs::path dir = out_dir();
  std::string body;
  for (const auto& stroke : head_first_arrow()) {
    body +=
        "<polyline fill=\"none\" stroke=\"#000\" stroke-width=\"2\" marker-end=\"url(#arrow)\" "
        "points=\"" +
        coordinates(stroke, ",") + "\"/>\n";
  }
  write_bytes(dir / "arrow.svg", svg_document(body));
  const BeforeAfter pictures = snap_and_render(dir, "arrow", ".svg", inkscape_png);
  ASSERT_EQ(pictures.failure, "");
  EXPECT_NE(pictures.snap_output.find("arrow"), std::string::npos) << pictures.snap_output;
  EXPECT_GE(inked_share(pictures.after, arrow_ink_points()), 0.9);
  EXPECT_GT(red_pixels(pictures.after, 290, 138, 312, 162), 5) << "the marker at the tail";
  EXPECT_EQ(red_pixels(pictures.after, 90, 125, 130, 175), 0) << "a marker at the head";
}

TEST(XournalDocuments, ArrowDrawnHeadFirstPointsWhereItWasDrawn) {
  std::string why;
  if (skip_without_xournal(why)) GTEST_SKIP() << why;
  const fs::path dir = out_dir();
  std::string layer;
  for (const auto& stroke : head_first_arrow()) layer += xopp_stroke(stroke, "2");
  write_bytes(dir / "arrow.xopp", gzip_bytes(xopp_document({layer})));
  const BeforeAfter pictures = snap_and_render(dir, "arrow", ".xopp", xournal_png);
  ASSERT_EQ(pictures.failure, "");
  EXPECT_NE(pictures.snap_output.find("arrow"), std::string::npos) << pictures.snap_output;
  EXPECT_GE(inked_share(pictures.after, arrow_ink_points()), 0.9);
}

TEST(InkscapeDocuments, DeepNestingOpens) {
  if (!have("inkscape")) GTEST_SKIP() << "inkscape is not installed (scripts/setup.sh installs it)";
  const fs::path dir = out_dir();
  std::string body;
  for (int i = 0; i < 10000; ++i) body += "<g>";
  body += "<polyline fill=\"none\" stroke=\"#000\" stroke-width=\"2\" points=\"" +
          coordinates(wobbly_circle(200, 150, 80), ",") + "\"/>";
  for (int i = 0; i < 10000; ++i) body += "</g>";
  write_bytes(dir / "deep.svg", svg_document(body + "\n"));
  const auto r = snap(dir / "deep.svg", dir / "deep-snapped.svg");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto png = inkscape_png((dir / "deep-snapped").string());
  ASSERT_EQ(png.exit_code, 0) << png.out;
  EXPECT_GE(
      inked_share(read_png((dir / "deep-snapped.png").string()), wobbly_circle(200, 150, 80, 90)),
      0.9);
}

} // namespace
} // namespace penshape::test
