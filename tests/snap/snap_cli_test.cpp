// `penshape snap` as a user runs it, on the fixture drawings (real $1 strokes): the strokes that
// are shapes are replaced by native elements close to the ink, everything else is unchanged, and
// bad input exits 2 naming the place without writing OUT.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <chrono>
#include <cmath>
#include <thread>

#include <filesystem>
#include <fstream>

#include "run_command.hpp"
#include "snap_checks.hpp"
#include "snap_fixtures.hpp"
#include "test_data.hpp"

namespace penshape::test {
namespace {

namespace fs = std::filesystem;
const std::string kCli = PENSHAPE_CLI;
constexpr unsigned kParse = pugi::parse_full | pugi::parse_ws_pcdata;

std::string gunzip_file(const fs::path& p) {
  gzFile f = gzopen(p.c_str(), "rb");
  if (f == nullptr) throw std::runtime_error("cannot open " + p.string());
  std::string out;
  char buf[65536];
  for (int n = 0; (n = gzread(f, buf, sizeof buf)) > 0;)
    out.append(buf, static_cast<std::size_t>(n));
  gzclose(f);
  return out;
}

class SnapCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("penshape-snap-cli-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  CommandResult snap(const std::string& args) {
    return run_command(kCli + " snap --local " + args + " 2>&1");
  }
  fs::path dir_;
};

// Checks a snapped SVG element against the raw stroke, in root coordinates (dy: the layer's
// translation).
void expect_close_shape(const pugi::xml_node& e, const FixtureStroke& raw, double dy,
                        double slack) {
  ASSERT_TRUE(e) << raw.id;
  EXPECT_EQ(std::string(e.attribute("data-penshape-class").value()), raw.expect) << raw.id;
  const std::string cert = e.attribute("data-penshape-certificate").value();
  const double bound = certificate_value(cert, "bound"), eps = certificate_value(cert, "epsilon");
  EXPECT_LE(bound, eps) << cert;
  std::vector<PointD> outline;
  bool closed = true;
  const std::string tag = e.name();
  if (tag == "circle") {
    const double cx = e.attribute("cx").as_double(), cy = e.attribute("cy").as_double() + dy;
    const double r = e.attribute("r").as_double();
    for (int i = 0; i < 720; ++i) {
      outline.push_back({cx + r * std::cos(i * M_PI / 360), cy + r * std::sin(i * M_PI / 360)});
    }
  } else if (tag == "rect") {
    const double x = e.attribute("x").as_double(), y = e.attribute("y").as_double() + dy;
    const double w = e.attribute("width").as_double(), h = e.attribute("height").as_double();
    outline = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
  } else if (tag == "polygon") {
    outline = pairs_of(e.attribute("points").value());
    for (PointD& p : outline) p.y += dy;
  } else if (tag == "path") {
    // An ellipse as two true arcs: "M p0 A rx,ry angle 0 1 p1 A ... p0 Z", p0 and p1 the ends of
    // the rx axis.
    std::string d = e.attribute("d").value();
    for (char& ch : d) ch = std::isalpha(static_cast<unsigned char>(ch)) ? ' ' : ch;
    const auto v = numbers_of(d);
    ASSERT_GE(v.size(), 9u);
    const PointD p0{v[0], v[1] + dy}, p1{v[7], v[8] + dy};
    const PointD c{(p0.x + p1.x) / 2, (p0.y + p1.y) / 2};
    const double rx = v[2], ry = v[3], t = v[4] * M_PI / 180;
    EXPECT_NEAR(std::hypot(p1.x - p0.x, p1.y - p0.y), 2 * rx, 1e-3);
    for (int i = 0; i < 720; ++i) {
      const double a = i * M_PI / 360, x = rx * std::cos(a), y = ry * std::sin(a);
      outline.push_back(
          {c.x + std::cos(t) * x - std::sin(t) * y, c.y + std::sin(t) * x + std::cos(t) * y});
    }
  } else {
    FAIL() << raw.id << ": unexpected element <" << tag << ">";
  }
  // Every point of the raw stroke lies within the certified bound of the clean path.
  EXPECT_LE(max_distance_to_polyline(raw.points, outline, closed), bound + slack) << raw.id;
}

TEST_F(SnapCli, InkscapeDrawing) {
  const Fixture f = inkscape_fixture();
  write_bytes(dir_ / "in.svg", f.text);
  const auto r = snap((dir_ / "in.svg").string() + " " + (dir_ / "out.svg").string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  pugi::xml_document in, out;
  ASSERT_TRUE(in.load_file((dir_ / "in.svg").c_str(), kParse));
  ASSERT_TRUE(out.load_file((dir_ / "out.svg").c_str(), kParse)) << r.out;
  // Pencil strokes: the path's own points; calligraphy: the outline's centre estimate, allow the
  // pen's width more.
  expect_close_shape(by_id(out, "pencil-circle"), f.strokes[0], 0, 0.5);
  expect_close_shape(by_id(out, "pencil-rect"), f.strokes[1], 0, 0.5);
  expect_close_shape(by_id(out, "callig-triangle"), f.strokes[3], 0, 6);
  expect_close_shape(by_id(out, "notes-circle"), f.strokes[4], 20, 0.5);
  // Style and place kept: the replacement sits where the path was among its siblings.
  EXPECT_NE(
      std::string(by_id(out, "pencil-circle").attribute("style").value()).find("stroke-width:8"),
      std::string::npos);
  pugi::xml_node next = by_id(out, "pencil-circle").next_sibling();
  while (next && next.type() != pugi::node_element) next = next.next_sibling();
  EXPECT_EQ(std::string(next.attribute("id").value()), "pencil-rect");
  EXPECT_EQ(std::string(by_id(out, "callig-triangle").parent().attribute("id").value()), "layer1");
  EXPECT_NE(std::string(by_id(out, "callig-triangle").attribute("style").value()).find("fill:none"),
            std::string::npos);
  // Unchanged: the freeform stroke, text, image, background, the named view.
  for (const char* id : {"pencil-pigtail", "label", "photo", "background", "note", "namedview1"}) {
    EXPECT_EQ(xml_of(by_id(out, id)), xml_of(by_id(in, id))) << id;
  }
  EXPECT_NE(r.out.find("4 of 5 strokes snapped (in-process)"), std::string::npos) << r.out;
}

TEST_F(SnapCli, OneLayerLeavesTheOtherAsItWas) {
  const Fixture f = inkscape_fixture();
  write_bytes(dir_ / "in.svg", f.text);
  const auto r =
      snap("--layer layer1 " + (dir_ / "in.svg").string() + " " + (dir_ / "out.svg").string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  pugi::xml_document in, out;
  ASSERT_TRUE(in.load_file((dir_ / "in.svg").c_str(), kParse));
  ASSERT_TRUE(out.load_file((dir_ / "out.svg").c_str(), kParse));
  EXPECT_EQ(xml_of(by_id(out, "layer2")), xml_of(by_id(in, "layer2")));
  EXPECT_STREQ(by_id(out, "pencil-circle").name(), "circle");
  // --ids: only the rectangle.
  const auto r2 =
      snap("--ids pencil-rect " + (dir_ / "in.svg").string() + " " + (dir_ / "ids.svg").string());
  ASSERT_EQ(r2.exit_code, 0) << r2.out;
  pugi::xml_document ids;
  ASSERT_TRUE(ids.load_file((dir_ / "ids.svg").c_str(), kParse));
  EXPECT_STREQ(by_id(ids, "pencil-circle").name(), "path");
  EXPECT_STRNE(by_id(ids, "pencil-rect").name(), "path");
  EXPECT_EQ(snap("--ids nosuch " + (dir_ / "in.svg").string() + " " + (dir_ / "x.svg").string())
                .exit_code,
            2);
}

TEST_F(SnapCli, XournalDocument) {
  const Fixture f = xopp_fixture();
  write_bytes(dir_ / "in.xopp", gzip_bytes(f.text));
  EXPECT_EQ(
      snap("--layer x " + (dir_ / "in.xopp").string() + " " + (dir_ / "o.xopp").string()).exit_code,
      2);
  const auto r = snap("--json " + (dir_ / "in.xopp").string() + " " + (dir_ / "out.xopp").string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string text = gunzip_file(dir_ / "out.xopp");
  pugi::xml_document in, out;
  ASSERT_TRUE(in.load_string(f.text.c_str(), kParse));
  ASSERT_TRUE(out.load_string(text.c_str(), kParse)) << text.substr(0, 200);
  const auto layers_in = in.child("xournal").child("page").children("layer");
  const auto layers_out = out.child("xournal").child("page").children("layer");
  std::vector<pugi::xml_node> lin(layers_in.begin(), layers_in.end()),
      lout(layers_out.begin(), layers_out.end());
  ASSERT_EQ(lout.size(), 2u);
  const auto stroke = [](const pugi::xml_node& layer, int k) {
    auto s = layer.child("stroke");
    while (k-- > 0) s = s.next_sibling("stroke");
    return s;
  };
  // The JSON names each replacement; its epsilon bounds the distance of the raw ink path to the
  // new stroke's points.
  EXPECT_NE(r.out.find("\"elements\":[\"/xournal/page[1]/layer[1]/stroke[1]\"],"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\"class\":\"circle\""), std::string::npos) << r.out;
  for (const auto& [layer, k, raw] :
       {std::tuple{0, 0, f.strokes[0]}, std::tuple{0, 1, f.strokes[1]},
        std::tuple{1, 0, f.strokes[3]}}) {
    const pugi::xml_node s = stroke(lout[static_cast<std::size_t>(layer)], k);
    const auto pts = pairs_of(s.child_value());
    EXPECT_GE(pts.size(), 5u);
    // The pressure stroke keeps its width profile: a width per segment after the tool's.
    const std::size_t widths = numbers_of(s.attribute("width").value()).size();
    EXPECT_TRUE(widths == 1 || widths == pts.size()) << widths << " widths, " << pts.size();
    EXPECT_STREQ(s.attribute("tool").value(), "pen");
    EXPECT_STREQ(s.attribute("color").value(),
                 stroke(lin[static_cast<std::size_t>(layer)], k).attribute("color").value());
    // 12.5% of the drawing's size bounds epsilon; the raw points are that close.
    EXPECT_LE(max_distance_to_polyline(raw.points, pts, false), 0.125 * 184) << raw.id;
  }
  // Unchanged: the pigtail, the text, the image, the background, the title.
  EXPECT_EQ(xml_of(stroke(lout[0], 2)), xml_of(stroke(lin[0], 2)));
  EXPECT_EQ(xml_of(lout[0].child("text")), xml_of(lin[0].child("text")));
  EXPECT_EQ(xml_of(lout[0].child("image")), xml_of(lin[0].child("image")));
  EXPECT_EQ(xml_of(lout[1].child("text")), xml_of(lin[1].child("text")));
  EXPECT_EQ(xml_of(out.child("xournal").child("page").child("background")),
            xml_of(in.child("xournal").child("page").child("background")));
  EXPECT_EQ(xml_of(out.child("xournal").child("title")),
            xml_of(in.child("xournal").child("title")));
}

TEST_F(SnapCli, NeverOverwritesInWithoutInPlace) {
  const Fixture f = inkscape_fixture();
  const fs::path in = dir_ / "in.svg";
  write_bytes(in, f.text);
  EXPECT_EQ(snap(in.string() + " " + in.string()).exit_code, 2);
  EXPECT_EQ(read_file(in), f.text);
  const auto r = snap("--in-place " + in.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(read_file(in), f.text);
  // No temporary files are left beside it.
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++files;
  EXPECT_EQ(files, 1u);
}

// The same drawing through a real penshaped (Geometry.Recognize): the same shapes, and the
// summary says where they were recognized. A socket where nothing listens falls back.
TEST_F(SnapCli, ThroughPenshapedWhenItRuns) {
  const Fixture f = inkscape_fixture();
  write_bytes(dir_ / "in.svg", f.text);
  const std::string socket = (dir_ / "p.sock").string();
  const std::string daemon = PENSHAPED, listen = "unix:" + socket;
  char* const argv[] = {const_cast<char*>(daemon.c_str()), const_cast<char*>("--config"),
                        const_cast<char*>("/dev/null"),    const_cast<char*>("--listen"),
                        const_cast<char*>(listen.c_str()), nullptr};
  pid_t pid = 0;
  ASSERT_EQ(::posix_spawn(&pid, daemon.c_str(), nullptr, nullptr, argv, environ), 0);
  for (int i = 0; i < 100 && !fs::exists(socket); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const auto remote =
      run_command(kCli + " snap --socket " + socket + " " + (dir_ / "in.svg").string() + " " +
                  (dir_ / "remote.svg").string() + " 2>&1");
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_EQ(remote.exit_code, 0) << remote.out;
  EXPECT_NE(remote.out.find("4 of 5 strokes snapped (penshaped at unix:" + socket + ")"),
            std::string::npos)
      << remote.out;
  const auto local = snap((dir_ / "in.svg").string() + " " + (dir_ / "local.svg").string());
  ASSERT_EQ(local.exit_code, 0) << local.out;
  pugi::xml_document a, b;
  ASSERT_TRUE(a.load_file((dir_ / "remote.svg").c_str()));
  ASSERT_TRUE(b.load_file((dir_ / "local.svg").c_str()));
  for (const auto& s : f.strokes) {
    EXPECT_STREQ(by_id(a, s.id).attribute("data-penshape-class").value(),
                 by_id(b, s.id).attribute("data-penshape-class").value())
        << s.id;
  }
  // Nothing listens there any more: in-process, with a note.
  const auto fallback =
      run_command(kCli + " snap --socket " + socket + " " + (dir_ / "in.svg").string() + " " +
                  (dir_ / "fallback.svg").string() + " 2>&1");
  EXPECT_EQ(fallback.exit_code, 0) << fallback.out;
  EXPECT_NE(fallback.out.find("recognizing in-process"), std::string::npos) << fallback.out;
  EXPECT_NE(fallback.out.find("4 of 5 strokes snapped (in-process)"), std::string::npos);
}

// Pressure widths one per segment (older files) are read too; the stroke snaps.
TEST_F(SnapCli, PressureWidthsPerSegment) {
  const Fixture f = xopp_fixture();
  std::string widths = "5.67";
  for (std::size_t i = 0; i + 1 < f.strokes[0].points.size(); ++i) widths += " 5";
  std::string pts;
  for (const PointD& p : f.strokes[0].points) {
    pts.append(std::to_string(p.x)).append(" ").append(std::to_string(p.y)).append(" ");
  }
  const std::string doc =
      "<xournal><page width=\"800\" height=\"600\"><layer><stroke tool=\"pen\" "
      "color=\"#000000ff\" width=\"" +
      widths + "\">" + pts + "</stroke></layer></page></xournal>";
  write_bytes(dir_ / "seg.xopp", gzip_bytes(doc));
  const auto r = snap((dir_ / "seg.xopp").string() + " " + (dir_ / "out.xopp").string());
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("page 1 layer 1 stroke 1 (line 1): circle"), std::string::npos) << r.out;
}

TEST_F(SnapCli, HelpStandardOutputAndNoGroup) {
  const auto help = run_command(kCli + " snap --help 2>&1");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--no-group"), std::string::npos);
  EXPECT_NE(help.out.find("recognize every stroke on its own"), std::string::npos) << help.out;
  EXPECT_NE(run_command(kCli + " --help").out.find("snap "), std::string::npos);
  // OUT "-": the document on standard output, the summary on stderr.
  const Fixture f = inkscape_fixture();
  write_bytes(dir_ / "in.svg", f.text);
  // (A subshell: run_command sends stderr to the captured output.)
  const auto out = run_command("(" + kCli + " snap --local --no-group " +
                               (dir_ / "in.svg").string() + " - 2>/dev/null)");
  ASSERT_EQ(out.exit_code, 0);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(out.out.c_str(), kParse)) << out.out.substr(0, 200);
  EXPECT_STREQ(by_id(doc, "pencil-circle").name(), "circle");
  EXPECT_EQ(snap("--json " + (dir_ / "in.svg").string() + " -").exit_code, 2);
  EXPECT_EQ(snap((dir_ / "in.svg").string()).exit_code, 2) << "OUT missing";
  EXPECT_EQ(snap("--pen-radius -1 " + (dir_ / "in.svg").string() + " o.svg").exit_code, 2);
}

// A square drawn as four sides, one path each, with small gaps and overshoots at the corners and
// a wobble along each side: grouped (the default) the four paths become one square element in
// the first path's place, the other three removed; with --no-group each side is its own line.
// An unrelated stroke far away stays what it is.
TEST_F(SnapCli, StrokesDrawnAsOneShapeBecomeOneElement) {
  const auto side = [](double x0, double y0, double x1, double y1) {
    std::string d = "M " + std::to_string(x0) + "," + std::to_string(y0);
    for (int k = 1; k <= 20; ++k) {
      const double t = k / 20.0, wobble = 0.6 * std::sin(7.0 * t);
      const double nx = -(y1 - y0), ny = x1 - x0, len = std::hypot(nx, ny);
      d += " L " + std::to_string(x0 + t * (x1 - x0) + wobble * nx / len) + "," +
           std::to_string(y0 + t * (y1 - y0) + wobble * ny / len);
    }
    return d;
  };
  const std::string style = "fill:none;stroke:#000000;stroke-width:4";
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"400\" height=\"400\">\n";
  const std::vector<std::string> sides = {side(101, 100, 199, 102), side(201, 99, 200, 198),
                                          side(199, 201, 102, 199), side(99, 198, 101, 103)};
  for (std::size_t i = 0; i < sides.size(); ++i) {
    svg += "<path id=\"side" + std::to_string(i + 1) + "\" style=\"" + style + "\" d=\"" +
           sides[i] + "\"/>\n";
  }
  svg += "<path id=\"far\" style=\"" + style + "\" d=\"" + side(300, 300, 380, 340) + "\"/>\n";
  svg += "</svg>\n";
  write_bytes(dir_ / "square.svg", svg);

  const auto grouped =
      snap("--json " + (dir_ / "square.svg").string() + " " + (dir_ / "grouped.svg").string());
  ASSERT_EQ(grouped.exit_code, 0) << grouped.out;
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((dir_ / "grouped.svg").c_str(), kParse));
  const pugi::xml_node shape = by_id(doc, "side1");
  ASSERT_TRUE(shape);
  const std::string cls = shape.attribute("data-penshape-class").value();
  EXPECT_TRUE(cls == "square" || cls == "rectangle") << cls << "\n" << grouped.out;
  for (const char* gone : {"side2", "side3", "side4"}) {
    EXPECT_FALSE(by_id(doc, gone)) << gone << " should have been replaced by the group";
  }
  EXPECT_STREQ(by_id(doc, "far").name(), "line");
  EXPECT_NE(grouped.out.find("\"elements\":[\"side1\",\"side2\",\"side3\",\"side4\"]"),
            std::string::npos)
      << grouped.out;

  const auto alone =
      snap("--no-group " + (dir_ / "square.svg").string() + " " + (dir_ / "alone.svg").string());
  ASSERT_EQ(alone.exit_code, 0) << alone.out;
  pugi::xml_document doc2;
  ASSERT_TRUE(doc2.load_file((dir_ / "alone.svg").c_str(), kParse));
  for (const char* id : {"side1", "side2", "side3", "side4"}) {
    EXPECT_STREQ(by_id(doc2, id).name(), "line") << id;
  }
}

struct BadCase {
  const char* name;
  std::string bytes;
  const char* message; // a part of the error message that names the place
};

TEST_F(SnapCli, BadInputExits2NamingThePlaceAndWritesNothing) {
  const std::string svg_head = "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<g>\n";
  const std::string xopp_head = "<xournal><page width=\"100\" height=\"100\"><layer>\n";
  const std::vector<BadCase> cases{
      {"malformed.svg", svg_head + "<path d=\"M0 0 L1 1\">\n</svg>", "not well-formed XML: line 4"},
      {"malformed.xopp", gzip_bytes(xopp_head + "<stroke>1 2 3 4</layer>"),
       "the gzip's content is not well-formed XML: line 2"},
      {"notxml.xopp", gzip_bytes("just some text, not XML"),
       "the gzip's content is not well-formed"},
      {"truncated.xopp", gzip_bytes(xopp_head).substr(0, 20), "gzip stream is truncated"},
      {"neither.xml", "<html><body/></html>", "neither format: its root is <html>"},
      // Dots, absurd widths and bad path data are left as drawn with a warning
      // (snap_documents_test.cpp): the apps open such files.
  };
  for (const BadCase& c : cases) {
    const fs::path in = dir_ / c.name, out = dir_ / (std::string("out-") + c.name);
    write_bytes(in, c.bytes);
    const auto r = snap(in.string() + " " + out.string());
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.out;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << c.name << ": " << r.out;
    EXPECT_FALSE(fs::exists(out)) << c.name;
  }
  // An existing OUT keeps its bytes.
  write_bytes(dir_ / "keep.svg", "old");
  EXPECT_EQ(snap((dir_ / "neither.xml").string() + " " + (dir_ / "keep.svg").string()).exit_code,
            2);
  EXPECT_EQ(read_file(dir_ / "keep.svg"), "old");
  EXPECT_EQ(snap((dir_ / "missing.svg").string() + " " + (dir_ / "o.svg").string()).exit_code, 2);
}

} // namespace
} // namespace penshape::test
