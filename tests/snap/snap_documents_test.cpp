// `penshape snap` on project-made documents that reproduce what real files showed (issue #29):
// what the apps accept is accepted (pressure 0/-1, dots, unreadable elements left with a warning,
// zip packages), what the drawer meant is kept (closed paths, direction, styles, calligraphy),
// no crash or runaway memory (deep nesting, gzip bomb), and only replaced elements change.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "run_command.hpp"
#include "snap_checks.hpp"
#include "snap_documents.hpp"
#include "snap_fixtures.hpp"

namespace penshape::test {
namespace {

namespace fs = std::filesystem;
using namespace docs;
const std::string kCli = PENSHAPE_CLI;

class SnapDocuments : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("penshape-snap-docs-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // Writes `bytes` to IN, snaps it to OUT with `args`; the output (stdout and stderr).
  CommandResult snap(const std::string& name, const std::string& bytes,
                     const std::string& args = "") {
    write_bytes(dir_ / name, bytes);
    return run_command(kCli + " snap --local " + args + " " + (dir_ / name).string() + " " +
                       (dir_ / ("out-" + name)).string() + " 2>&1");
  }
  std::string out(const std::string& name) {
    std::ifstream in(dir_ / ("out-" + name), std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  // The element with this id in OUT (null when OUT is no XML or has none).
  pugi::xml_node out_element(const std::string& name, const std::string& id) {
    if (!out_doc_.load_string(out(name).c_str())) return {};
    return by_id(out_doc_, id);
  }
  fs::path dir_;
  pugi::xml_document out_doc_;
};

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

// Pressure widths one per point (Xournal++ 1.0.x ends each stroke with -1) or with 0 at pen
// lift: read as Xournal++ reads them, and the circle snaps.
TEST_F(SnapDocuments, PressureZeroAndMinusOneAreAccepted) {
  const auto circle = wobbly_circle(200, 150, 80);
  std::string minus_one = "2", zero = "2";
  for (std::size_t i = 0; i < circle.size(); ++i) {
    minus_one += i + 1 < circle.size() ? " 2.1" : " -1";
    zero += i + 2 < circle.size() ? " 2.1" : " 0";
  }
  for (const auto& [name, width] : {std::pair{"minus1.xopp", minus_one}, {"zero.xopp", zero}}) {
    const auto r = snap(name, gzip_bytes(xopp_document({xopp_stroke(circle, width)})));
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.out;
    EXPECT_TRUE(contains(r.out, "stroke 1 (line 7): circle")) << name << ": " << r.out;
  }
  // Pressure 0 in the middle: Xournal++ draws two pieces; snap leaves them, saying so.
  std::string split = "2";
  for (std::size_t i = 0; i + 1 < circle.size(); ++i) split += i == 30 ? " 0" : " 2";
  const auto r = snap("split.xopp", gzip_bytes(xopp_document({xopp_stroke(circle, split)})));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "warning: page 1 layer 1 stroke 1 (line 7): drawn in pieces"))
      << r.out;
}

// A dot is a dot: left as drawn, and a document with nothing snapped comes out byte for byte.
TEST_F(SnapDocuments, DotsAreLeftAsDrawn) {
  const std::string xopp = gzip_bytes(xopp_document({xopp_stroke({{50, 50}}, "2")}));
  auto r = snap("dot.xopp", xopp);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(out("dot.xopp"), xopp);
  const std::string svg = svg_document(
      "<path id=\"dot\" style=\"fill:none;stroke:#000;stroke-width:3\" d=\"M 5 5\"/>\n");
  r = snap("dot.svg", svg);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(out("dot.svg"), svg);
}

// An element that cannot be a stroke is left as it is, named in a warning; the rest snaps.
TEST_F(SnapDocuments, UnreadableElementsAreLeftWithAWarning) {
  const std::string circle = coordinates(wobbly_circle(200, 150, 80), ",");
  const std::string svg = svg_document(
      "<line id=\"fat\" x1=\"0\" y1=\"0\" x2=\"9\" y2=\"9\" stroke=\"red\" stroke-width=\"1e7\"/>\n"
      "<path id=\"bad\" stroke=\"red\" fill=\"none\" d=\"M 1 1 L 2\"/>\n"
      "<path id=\"far\" stroke=\"red\" fill=\"none\" transform=\"scale(1e308)\" d=\"M 1 1 L 9 "
      "9\"/>\n<path id=\"open-fill\" fill=\"#00f\" d=\"M 10 10 L 20 10\"/>\n"
      "<polyline id=\"c\" stroke=\"#000\" stroke-width=\"2\" fill=\"none\" points=\"" +
      circle + "\"/>\n");
  auto r = snap("warn.svg", svg);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  for (const char* w : {"warning: line#fat (line 4): stroke-width 1e7",
                        "warning: path#bad (line 5): path data", "warning: path#far (line 6)"}) {
    EXPECT_TRUE(contains(r.out, w)) << w << "\n" << r.out;
  }
  EXPECT_TRUE(contains(r.out, "polyline#c (line 8): circle")) << r.out;
  const auto pts = wobbly_circle(200, 150, 80);
  const std::string xopp =
      xopp_document({xopp_stroke(pts, "-2") + xopp_stroke(pts, "1 1 1e9") +
                     "<stroke tool=\"pen\" color=\"#000000ff\" width=\"1\">1e308 0 0 1</stroke>\n" +
                     xopp_stroke(pts, "2")});
  r = snap("warn.xopp", gzip_bytes(xopp));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  for (const char* w : {"stroke 1 (line 7): width -2", "stroke 2 (line 8): width 1000000000",
                        "stroke 3 (line 9): coordinates beyond"}) {
    EXPECT_TRUE(contains(r.out, w)) << w << "\n" << r.out;
  }
  EXPECT_TRUE(contains(r.out, "stroke 4 (line 10): circle")) << r.out;
  // --json: the warnings as objects, replacements by locator; --quiet: no warnings on stderr.
  r = snap("warn2.xopp", gzip_bytes(xopp), "--json");
  EXPECT_TRUE(contains(r.out, "{\"warning\":\"page 1 layer 1 stroke 1")) << r.out;
  EXPECT_TRUE(contains(r.out, "\"elements\":[\"/xournal/page[1]/layer[1]/stroke[4]\"]")) << r.out;
  r = snap("warn3.xopp", gzip_bytes(xopp), "--quiet");
  EXPECT_FALSE(contains(r.out, "warning")) << r.out;
}

// Only a document the apps cannot open is refused, with exit 2 and nothing written.
TEST_F(SnapDocuments, OnlyWhatTheAppsCannotOpenIsRefused) {
  for (const auto& [name, bytes] : std::vector<std::pair<std::string, std::string>>{
           {"bad.svg", "<svg><g></svg>"},
           {"bad.xopp", gzip_bytes("<xournal><page>").substr(0, 12)},
           {"nocontent.xopp", zip_package({{"mimetype", "application/xournal++"}})}}) {
    const auto r = snap(name, bytes);
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.out;
    EXPECT_FALSE(fs::exists(dir_ / ("out-" + name))) << name;
  }
}

// A zip-packaged .xopp: read, written back as a zip, attachments and other entries kept.
TEST_F(SnapDocuments, ZipPackagedXoppKeepsItsAttachments) {
  const std::string xml = xopp_document(
      {xopp_stroke(wobbly_circle(200, 150, 80), "2") +
       "<image left=\"1\" top=\"1\" right=\"9\" bottom=\"9\" filename=\"images/1.png\"/>\n"});
  const std::string png("\x89PNG\r\n\x1a\n not really", 19);
  const std::string zip = zip_package({{"mimetype", "application/xournal++"},
                                       {"META-INF/version", "current=1.1.3\nmin=1.1.0\n"},
                                       {"content.xml", xml},
                                       {"images/1.png", png}});
  const auto r = snap("package.xopp", zip);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "circle")) << r.out;
  const auto entries = zip_entries(out("package.xopp"));
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_EQ(entries.at("mimetype"), "application/xournal++");
  EXPECT_EQ(entries.at("images/1.png"), png);
  EXPECT_NE(entries.at("content.xml"), xml);
  EXPECT_TRUE(contains(entries.at("content.xml"), "<image left=\"1\""));
}

// A closed subpath stays closed: the closing side is ink, and a closed square is a rectangle.
TEST_F(SnapDocuments, ClosedSquareComesOutClosed) {
  const auto r = snap("closed.svg", svg_document("<path id=\"sq\" style=\"fill:none;stroke:#000;"
                                                 "stroke-width:2\" d=\"M100 100 L200 100 L200 "
                                                 "200 L100 200 Z\"/>\n"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const pugi::xml_node e = out_element("closed.svg", "sq");
  ASSERT_STREQ(e.name(), "rect") << r.out;
  EXPECT_NEAR(e.attribute("x").as_double(), 100, 1);
  EXPECT_NEAR(e.attribute("width").as_double(), 100, 1);
  EXPECT_NEAR(e.attribute("height").as_double(), 100, 1);
}

// Strokes drawn right to left with an arrowhead marker keep their direction (the marker stays at
// the end where the drawer stopped).
TEST_F(SnapDocuments, MarkedStrokesKeepTheirDirection) {
  const std::string line = coordinates(wobbly_line({300, 100}, {100, 100}), ",");
  const std::string bent = coordinates(wobbly_line({300, 250}, {200, 250}, 12), ",") + " " +
                           coordinates(wobbly_line({200, 250}, {200, 150}, 12), ",");
  const auto r = snap("marker.svg",
                      svg_document("<polyline id=\"l\" marker-end=\"url(#arrow)\" fill=\"none\" "
                                   "stroke=\"#000\" stroke-width=\"2\" points=\"" +
                                   line +
                                   "\"/>\n<polyline id=\"b\" marker-end=\"url(#arrow)\" "
                                   "fill=\"none\" stroke=\"#000\" stroke-width=\"2\" "
                                   "points=\"" +
                                   bent + "\"/>\n"),
                      "--no-group");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const pugi::xml_node l = out_element("marker.svg", "l");
  ASSERT_STREQ(l.name(), "line") << r.out;
  EXPECT_NEAR(l.attribute("x1").as_double(), 300, 2);
  EXPECT_NEAR(l.attribute("x2").as_double(), 100, 2);
  EXPECT_STREQ(l.attribute("marker-end").value(), "url(#arrow)");
  const pugi::xml_node b = out_element("marker.svg", "b");
  ASSERT_STREQ(b.name(), "polyline") << r.out;
  const auto pts = pairs_of(b.attribute("points").value());
  ASSERT_GE(pts.size(), 2u);
  EXPECT_NEAR(pts.front().x, 300, 2);
  EXPECT_NEAR(pts.back().y, 150, 2);
}

// The points of an SVG path's data (M/L commands, "x,y" pairs).
std::vector<PointD> path_points(std::string d) {
  for (char& c : d) c = c == 'M' || c == 'L' || c == ',' ? ' ' : c;
  return pairs_of(d);
}

bool near(PointD a, PointD b, double within) { return std::hypot(a.x - b.x, a.y - b.y) <= within; }

// An arrow drawn in two strokes, the shaft (100, 200) -> (300, 200) and the head's barbs meeting
// at (300, 200): shaft first, or head first and then the shaft back to the tail. Either way the
// clean arrow points where the head was drawn, and its path runs as the pen did: from the tail to
// the head, or from the head (its barbs first) to the tail, so marker-end sits where the drawer
// stopped. In both formats.
TEST_F(SnapDocuments, ArrowsPointWhereTheirHeadWasDrawn) {
  const PointD tail{100, 200}, tip{300, 200}, barb1{280, 185}, barb2{280, 215};
  std::vector<PointD> head = wobbly_line(barb1, tip, 8);
  const auto second_barb = wobbly_line(tip, barb2, 8);
  head.insert(head.end(), second_barb.begin() + 1, second_barb.end());
  for (const bool head_first : {false, true}) {
    const std::vector<std::vector<PointD>> strokes =
        head_first ? std::vector{head, wobbly_line(tip, tail, 24)}
                   : std::vector{wobbly_line(tail, tip, 24), head};
    std::string svg, xopp;
    for (std::size_t i = 0; i < strokes.size(); ++i) {
      svg += "<polyline id=\"s" + std::to_string(i) +
             "\" marker-end=\"url(#arrow)\" fill=\"none\" stroke=\"#000\" stroke-width=\"2\" "
             "points=\"" +
             coordinates(strokes[i], ",") + "\"/>\n";
      xopp += xopp_stroke(strokes[i], "2");
    }
    const std::string name = head_first ? "head-first" : "shaft-first";
    const auto r = snap(name + ".svg", svg_document(svg));
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const pugi::xml_node e = out_element(name + ".svg", "s0");
    ASSERT_STREQ(e.attribute("data-penshape-class").value(), "arrow") << name << ": " << r.out;
    EXPECT_STREQ(e.attribute("marker-end").value(), "url(#arrow)");
    const auto svg_pts = path_points(e.attribute("d").value());
    const auto x = snap(name + ".xopp", xopp_document({xopp}));
    ASSERT_EQ(x.exit_code, 0) << x.out;
    ASSERT_TRUE(contains(x.out, "stroke 1 (line 7): arrow")) << name << ": " << x.out;
    const std::string text = out(name + ".xopp");
    const auto stroke_at = text.find("<stroke");
    const auto xopp_pts = pairs_of(text.substr(text.find('>', stroke_at) + 1));
    for (const auto& pts : {svg_pts, xopp_pts}) {
      ASSERT_EQ(pts.size(), 5u) << name; // shaft (2) and head (3), as subpaths or one line
      // The head where it was drawn: the point its barbs meet is the tip.
      const std::size_t at_tip = head_first ? 1 : pts.size() - 2;
      EXPECT_TRUE(near(pts[at_tip], tip, 3)) << name << " tip at " << pts[at_tip].x;
      EXPECT_TRUE(near(pts[at_tip - 1], barb1, 4) || near(pts[at_tip - 1], barb2, 4)) << name;
      // The path runs as drawn: it ends at the tail when the head came first.
      EXPECT_TRUE(near(head_first ? pts.back() : pts.front(), tail, 3)) << name;
    }
  }
}

// A pressure stroke keeps its width profile in Xournal++, so its certificate covers the widths
// written and drawn (width_profile.hpp): a circle whose widths vary a little snaps with the
// widened bound; one with a stretch drawn 18 times as wide as the rest snaps no more, since the
// written widths' spread around the median pen no longer fits the tolerance.
TEST_F(SnapDocuments, PressureCertificateCoversTheWidthsDrawn) {
  const auto circle = wobbly_circle(200, 150, 80);
  for (const double wide : {2.8, 36.0}) {
    std::string widths = "2";
    for (std::size_t i = 0; i + 1 < circle.size(); ++i) {
      widths.append(" ").append(i >= 20 && i < 28 ? std::to_string(wide) : "2");
    }
    const std::string name = std::string("pressure").append(wide < 3 ? "-thin" : "-wide") + ".xopp";
    const auto r = snap(name, gzip_bytes(xopp_document({xopp_stroke(circle, widths)})));
    ASSERT_EQ(r.exit_code, 0) << r.out;
    if (wide < 3) {
      EXPECT_TRUE(contains(r.out, "stroke 1 (line 7): circle")) << r.out;
      EXPECT_TRUE(contains(r.out, "+width_profile)")) << r.out;
    } else {
      EXPECT_TRUE(contains(r.out,
                           "circle not within the tolerance with the widths drawn: left "
                           "as drawn"))
          << r.out;
      EXPECT_TRUE(contains(r.out, "0 of 1 strokes snapped")) << r.out;
    }
  }
}

// The four sides of a rectangle, drawn one after the other: one rectangle when they share colour
// and width; with alternating colours nothing is merged and every colour survives.
TEST_F(SnapDocuments, StrokesOfDifferentStylesNeverMerge) {
  const std::vector<std::vector<PointD>> sides{
      wobbly_line({100, 100}, {300, 100}), wobbly_line({300, 100}, {300, 200}),
      wobbly_line({300, 200}, {100, 200}), wobbly_line({100, 200}, {100, 100})};
  const auto page = [&](const char* second) {
    std::string body;
    for (std::size_t i = 0; i < sides.size(); ++i) {
      body += "<polyline id=\"s" + std::to_string(i) + "\" fill=\"none\" stroke=\"" +
              (i % 2 == 1 ? second : "#000000") + "\" stroke-width=\"2\" points=\"" +
              coordinates(sides[i], ",") + "\"/>\n";
    }
    return svg_document(body);
  };
  auto r = snap("same.svg", page("#000000"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "1 of 4 strokes snapped")) << r.out;
  r = snap("mixed.svg", page("#ff0000"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  for (int i = 0; i < 4; ++i) {
    const std::string id = std::string(1, 's').append(std::to_string(i));
    const pugi::xml_node e = out_element("mixed.svg", id);
    ASSERT_TRUE(e) << id << " was deleted: " << r.out;
    EXPECT_STREQ(e.attribute("stroke").value(), i % 2 == 1 ? "#ff0000" : "#000000");
  }
}

// A calligraphy outline whose width varies (2 to 12 units) is left as drawn.
TEST_F(SnapDocuments, VariableWidthCalligraphyStays) {
  const auto centre = wobbly_line({100, 150}, {300, 150}, 40);
  std::vector<PointD> upper, lower;
  for (std::size_t i = 0; i < centre.size(); ++i) {
    const double w = 1 + 5.0 * static_cast<double>(i) / static_cast<double>(centre.size() - 1);
    upper.push_back({centre[i].x, centre[i].y - w});
    lower.insert(lower.begin(), {centre[i].x, centre[i].y + w});
  }
  upper.insert(upper.end(), lower.begin(), lower.end());
  const std::string svg = svg_document("<path id=\"cal\" style=\"fill:#000;stroke:none\" d=\"M " +
                                       coordinates(upper, ",") + " Z\"/>\n");
  const auto r = snap("cal.svg", svg);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(out("cal.svg"), svg) << r.out;
}

// 10,000 nested groups: read without recursion (exit 0), the stroke at the bottom found.
TEST_F(SnapDocuments, DeepNestingNeverCrashes) {
  std::string body;
  for (int i = 0; i < 10000; ++i) body += "<g>";
  body += "<polyline fill=\"none\" stroke=\"#000\" stroke-width=\"2\" points=\"" +
          coordinates(wobbly_circle(200, 150, 80), ",") + "\"/>";
  for (int i = 0; i < 10000; ++i) body += "</g>";
  const auto r = snap("deep.svg", svg_document(body + "\n"), "--json");
  ASSERT_EQ(r.exit_code, 0) << r.out.substr(0, 500);
  EXPECT_TRUE(contains(r.out, "\"elements\":[\"/svg[1]/g[1]/g[1]/g[1]")) << r.out.substr(0, 300);
}

// A gzip bomb (1.1 GiB of zeros in ~1 MB) stops at the 1 GiB limit, exit 2, and the process
// never holds twice the limit.
TEST_F(SnapDocuments, GzipBombStopsAtItsLimit) {
  const auto r = snap("bomb.xopp", gzip_of_zeros((std::size_t{1} << 30) + (std::size_t{1} << 27)));
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "expands beyond 1073741824 bytes")) << r.out;
  rusage usage{};
  ASSERT_EQ(::getrusage(RUSAGE_CHILDREN, &usage), 0);
  EXPECT_LT(usage.ru_maxrss, 1536L * 1024) << "KiB at the peak";
}

// Only replaced elements change: comments, entities, whitespace and attribute quoting elsewhere
// come out byte for byte.
TEST_F(SnapDocuments, UntouchedBytesStayTheSame) {
  const std::string head =
      "<?xml version=\"1.0\"?>\n<!DOCTYPE svg [ <!ENTITY who \"World\"> ]>\n"
      "<svg xmlns='http://www.w3.org/2000/svg' width='400' height='300'>\n"
      "  <!-- a comment -->\n  <text x = '10' y='20'>Hello &who;</text>\n  ";
  const std::string stroke =
      "<polyline fill=\"none\" stroke=\"#000\" stroke-width=\"2\" "
      "points=\"" +
      coordinates(wobbly_circle(200, 150, 80), ",") + "\"/>";
  const std::string tail =
      "\n  <path d='M 0 0 C 1 1 2 2 3 3' stroke='#000' fill='#f00'/>\n</svg>\n";
  const auto r = snap("bytes.svg", head + stroke + tail);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string o = out("bytes.svg");
  ASSERT_GE(o.size(), head.size() + tail.size());
  EXPECT_EQ(o.substr(0, head.size()), head);
  EXPECT_EQ(o.substr(o.size() - tail.size()), tail);
  EXPECT_TRUE(contains(o.substr(head.size()), "<circle")) << o;
}

// CRLF line ends are kept outside the replacement; a UTF-16 document (whose offsets the parser
// does not keep) is written whole, in UTF-16.
TEST_F(SnapDocuments, LineEndsAndOtherEncodings) {
  const std::string stroke =
      "<polyline fill=\"none\" stroke=\"#000\" stroke-width=\"2\" points=\"" +
      coordinates(wobbly_circle(200, 150, 80), ",") + "\"/>";
  const std::string head = "<svg xmlns=\"http://www.w3.org/2000/svg\">\r\n<text>a</text>\r\n";
  auto r = snap("crlf.svg", head + stroke + "\r\n</svg>\r\n");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(out("crlf.svg").substr(0, head.size()), head);
  EXPECT_TRUE(contains(out("crlf.svg"), "/>\r\n</svg>\r\n"));
  // UTF-16: a circle, and a rectangle drawn side by side (the three later sides leave the tree).
  std::string ascii = "<?xml version=\"1.0\" encoding=\"UTF-16\"?>\n";
  ascii.append(head).append(stroke);
  const std::vector<PointD> corners{{100, 300}, {300, 300}, {300, 400}, {100, 400}, {100, 300}};
  for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
    ascii.append("<polyline fill=\"none\" stroke=\"#000\" stroke-width=\"2\" points=\"")
        .append(coordinates(wobbly_line(corners[i], corners[i + 1]), ","))
        .append("\"/>");
  }
  ascii.append("</svg>");
  std::string utf16 = "\xff\xfe"; // little-endian, with its byte order mark
  for (const char c : ascii) utf16 += std::string{c, '\0'};
  r = snap("utf16.svg", utf16);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string o = out("utf16.svg");
  ASSERT_GE(o.size(), 2u);
  EXPECT_EQ(o.substr(0, 2), "\xff\xfe");
  std::string narrow; // the ASCII of the output
  for (std::size_t i = 2; i < o.size(); i += 2) narrow += o[i];
  EXPECT_TRUE(contains(narrow, "<circle")) << r.out;
  EXPECT_TRUE(contains(narrow, "<rect") || contains(narrow, "<polygon")) << narrow;
  EXPECT_FALSE(contains(narrow, "<polyline")) << narrow;
}

} // namespace
} // namespace penshape::test
