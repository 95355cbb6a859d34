// Building the snap test drawings (see snap_fixtures.hpp).
#include "snap_fixtures.hpp"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

#include "dollar_xml.hpp"
#include "stroke_files.hpp"
#include "stroke_gen.hpp"
#include "test_data.hpp"

namespace penshape::test {
namespace {

constexpr const char* kPng =
    "iVBORw0KGgoAAAANSUhEUgAAAAgAAAAICAIAAABLbSncAAAAEElEQVR4nGNgiDqBHQ0tCQAibEiBFNRCGAAAAABJRU5Er"
    "kJggg==";

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

std::string pt(PointD p) {
  std::string s = num(p.x);
  s.append(",").append(num(p.y));
  return s;
}

// " x,y": appended piece by piece (g++ 12 warns falsely, -Wrestrict, on " " + string).
std::string spt(PointD p) {
  std::string s(" ");
  s.append(pt(p));
  return s;
}

// Catmull-Rom through the points as cubic Bezier pieces (Inkscape's Pencil writes curves).
std::string smooth_d(const std::vector<PointD>& p, bool relative) {
  std::string d = "M " + pt(p[0]);
  d += relative ? " c" : " C";
  const std::size_t n = p.size();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const PointD a = p[i == 0 ? 0 : i - 1], b = p[i], c = p[i + 1], e = p[std::min(i + 2, n - 1)];
    PointD c1{b.x + (c.x - a.x) / 6, b.y + (c.y - a.y) / 6};
    PointD c2{c.x - (e.x - b.x) / 6, c.y - (e.y - b.y) / 6};
    PointD end = c;
    if (relative) {
      c1 = {c1.x - b.x, c1.y - b.y}, c2 = {c2.x - b.x, c2.y - b.y}, end = {c.x - b.x, c.y - b.y};
    }
    d.append(spt(c1)).append(spt(c2)).append(spt(end));
  }
  return d;
}

std::string polyline_d(const std::vector<PointD>& p) {
  std::string d = "M " + pt(p[0]) + " L";
  for (std::size_t i = 1; i < p.size(); ++i) d += spt(p[i]);
  return d;
}

// The outline a Calligraphy stroke of half-width w leaves: one edge forward, a round cap, the
// other edge back, a round cap.
std::string calligraphy_d(const std::vector<PointD>& p, double w) {
  std::vector<PointD> left, right;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const PointD a = p[i == 0 ? 0 : i - 1], b = p[std::min(i + 1, p.size() - 1)];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const PointD n{-(b.y - a.y) / len, (b.x - a.x) / len};
    left.push_back({p[i].x + w * n.x, p[i].y + w * n.y});
    right.push_back({p[i].x - w * n.x, p[i].y - w * n.y});
  }
  std::string d = "M " + pt(left[0]) + " L";
  for (std::size_t i = 1; i < left.size(); ++i) d += spt(left[i]);
  d += " A " + num(w) + "," + num(w) + " 0 0 0 " + pt(right.back()) + " L";
  for (std::size_t i = right.size() - 1; i-- > 0;) d += spt(right[i]);
  d += " A " + num(w) + "," + num(w) + " 0 0 0 " + pt(left[0]) + " Z";
  return d;
}

// A hand-drawn stroke made by the stroke generator (tests/support/gen): `kind` drawn with `seed`,
// written as a $1 gesture log in this process's temporary folder.
std::string gesture(const char* kind, std::uint64_t seed) {
  gen::StrokeGenerator generator(seed);
  const gen::Drawing d = generator.draw(kind);
  const auto path =
      std::filesystem::temp_directory_path() /
      ("penshape_snap_" + std::to_string(::getpid()) + "_" + kind + std::to_string(seed) + ".xml");
  std::ofstream(path) << gen::to_dollar_xml(d.strokes.front(), kind, 1, gen::Speed::kMedium);
  return path.string();
}

std::string points_text(const std::vector<PointD>& p) {
  std::string s;
  for (const PointD& q : p) {
    if (!s.empty()) s += ' ';
    s.append(num(q.x)).append(" ").append(num(q.y));
  }
  return s;
}

} // namespace

std::vector<PointD> placed_gesture(const std::string& file, double x0, double y0, double size) {
  std::vector<PointD> pts;
  for (const StrokePoint& p : dollar::read_dollar_xml(file).points) {
    const PointD q{p.x, p.y};
    // A pixel repeated at once or after one step back (a pause, a jitter) gives a Calligraphy
    // outline no direction there: drop it.
    const auto same = [&](std::size_t back) {
      return pts.size() >= back && q.x == pts[pts.size() - back].x &&
             q.y == pts[pts.size() - back].y;
    };
    if (!same(1) && !same(2)) pts.push_back(q);
  }
  double minx = 1e300, miny = 1e300, maxx = -1e300, maxy = -1e300;
  for (const PointD& p : pts) {
    minx = std::min(minx, p.x), miny = std::min(miny, p.y);
    maxx = std::max(maxx, p.x), maxy = std::max(maxy, p.y);
  }
  const double s = size / std::max(maxx - minx, maxy - miny);
  for (PointD& p : pts) p = {x0 + (p.x - minx) * s, y0 + (p.y - miny) * s};
  return pts;
}

Fixture inkscape_fixture() {
  Fixture f;
  const auto circle = placed_gesture(gesture("circle", 1), 40, 40, 120);
  const auto rect = placed_gesture(gesture("rectangle", 4), 220, 40, 150);
  const auto pig = placed_gesture(gesture("spiral", 2), 440, 40, 120);
  const auto tri = placed_gesture(gesture("triangle", 5), 40, 260, 140);
  const auto notes = placed_gesture(gesture("circle", 7), 320, 380, 110);
  std::vector<PointD> notes_page;
  notes_page.reserve(notes.size());
  for (const PointD& p : notes) notes_page.push_back({p.x, p.y + 20});
  f.strokes = {{"pencil-circle", circle, 8, "circle"},
               {"pencil-rect", rect, 8, "rectangle"},
               {"pencil-pigtail", pig, 8, ""},
               {"callig-triangle", tri, 8, "triangle"},
               {"notes-circle", notes_page, 6, "circle"}};
  const std::string pencil =
      "fill:none;stroke:#000000;stroke-width:8;stroke-linecap:round;"
      "stroke-linejoin:round;stroke-opacity:1";
  std::ostringstream text;
  text
      << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
         "<!-- Created with Inkscape (http://www.inkscape.org/) -->\n"
         "<svg width=\"800\" height=\"600\" viewBox=\"0 0 800 600\" version=\"1.1\" id=\"svg1\"\n"
         "   inkscape:version=\"1.2.2 (b0a8486541, 2022-12-01)\" sodipodi:docname=\"drawing.svg\"\n"
         "   xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"\n"
         "   xmlns:sodipodi=\"http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd\"\n"
         "   xmlns:xlink=\"http://www.w3.org/1999/xlink\"\n"
         "   xmlns=\"http://www.w3.org/2000/svg\" xmlns:svg=\"http://www.w3.org/2000/svg\">\n"
         "  <sodipodi:namedview id=\"namedview1\" pagecolor=\"#ffffff\" "
         "inkscape:current-layer=\"layer1\" />\n"
         "  <defs id=\"defs1\" />\n"
         "  <rect id=\"background\" x=\"0\" y=\"0\" width=\"800\" height=\"600\" "
         "style=\"fill:#ffffff\" />\n"
         "  <g inkscape:label=\"Ink\" inkscape:groupmode=\"layer\" id=\"layer1\">\n"
         "    <path style=\""
      << pencil << "\" d=\"" << smooth_d(circle, false)
      << "\" id=\"pencil-circle\" sodipodi:nodetypes=\"cc\" />\n"
         "    <path style=\""
      << pencil << "\" d=\"" << smooth_d(rect, true)
      << "\" id=\"pencil-rect\" />\n"
         "    <path style=\""
      << pencil << "\" d=\"" << polyline_d(pig)
      << "\" id=\"pencil-pigtail\" />\n"
         "    <path style=\"fill:#000000;fill-opacity:1;fill-rule:nonzero;stroke:none\" d=\""
      << calligraphy_d(tri, 4)
      << "\" id=\"callig-triangle\" />\n"
         "    <text x=\"300\" y=\"300\" id=\"label\" style=\"font-size:24px;fill:#000000\">Snap "
         "me</text>\n"
         "    <image x=\"600\" y=\"280\" width=\"80\" height=\"80\" id=\"photo\" "
         "preserveAspectRatio=\"none\" style=\"image-rendering:optimizeSpeed\" "
         "xlink:href=\"data:image/png;base64,"
      << kPng
      << "\" />\n"
         "  </g>\n"
         "  <g inkscape:label=\"Notes\" inkscape:groupmode=\"layer\" id=\"layer2\" "
         "transform=\"translate(0,20)\">\n"
         "    <path style=\"fill:none;stroke:#0000ff;stroke-width:6\" d=\""
      << smooth_d(notes, false)
      << "\" id=\"notes-circle\" />\n"
         "    <text x=\"40\" y=\"560\" id=\"note\" style=\"font-size:20px\">left as drawn</text>\n"
         "  </g>\n"
         "</svg>\n";
  f.text = text.str();
  return f;
}

Fixture xopp_fixture() {
  Fixture f;
  const auto circle = placed_gesture(gesture("circle", 1), 60, 60, 110);
  const auto rect = placed_gesture(gesture("rectangle", 4), 260, 60, 130);
  const auto pig = placed_gesture(gesture("spiral", 2), 480, 60, 110);
  const auto notes = placed_gesture(gesture("circle", 7), 320, 340, 110);
  // Pressure: widths between 60% and 100% of the tool's 5.67 pt (very thick), as a pen pressed
  // unevenly.
  std::string widths = "5.67";
  for (std::size_t i = 0; i < circle.size(); ++i) {
    widths.append(" ").append(num(5.67 * (0.8 + 0.2 * std::sin(static_cast<double>(i) * 0.3))));
  }
  f.strokes = {{"page 1 layer 1 stroke 1", circle, 5.67, "circle"},
               {"page 1 layer 1 stroke 2", rect, 5.67, "rectangle"},
               {"page 1 layer 1 stroke 3", pig, 5.67, ""},
               {"page 1 layer 2 stroke 1", notes, 5.67, "circle"}};
  std::ostringstream text;
  text << "<?xml version=\"1.0\" standalone=\"no\"?>\n"
          "<xournal creator=\"Xournal++ 1.1.3\" fileversion=\"4\">\n"
          "<title>Xournal++ document - see https://github.com/xournalpp/xournalpp</title>\n"
          "<page width=\"800.00000000\" height=\"600.00000000\">\n"
          "<background type=\"solid\" color=\"#ffffffff\" style=\"plain\"/>\n"
          "<layer>\n"
          "<stroke tool=\"pen\" ts=\"0\" fn=\"\" color=\"#000000ff\" width=\""
       << widths << "\">" << points_text(circle)
       << "</stroke>\n"
          "<stroke tool=\"pen\" ts=\"0\" fn=\"\" color=\"#000000ff\" width=\"5.67\">"
       << points_text(rect)
       << "</stroke>\n"
          "<stroke tool=\"pen\" ts=\"0\" fn=\"\" color=\"#000000ff\" width=\"5.67\">"
       << points_text(pig)
       << "</stroke>\n"
          "<text font=\"Sans\" size=\"20.00000000\" x=\"60.00000000\" y=\"300.00000000\" "
          "color=\"#000000ff\" ts=\"0\" fn=\"\">Snap me</text>\n"
          "<image left=\"600.00000000\" top=\"300.00000000\" right=\"680.00000000\" "
          "bottom=\"380.00000000\">"
       << std::string(kPng)
       << "</image>\n"
          "</layer>\n"
          "<layer>\n"
          "<stroke tool=\"pen\" ts=\"0\" fn=\"\" color=\"#3333ccff\" width=\"5.67\">"
       << points_text(notes)
       << "</stroke>\n"
          "<text font=\"Sans\" size=\"16.00000000\" x=\"60.00000000\" y=\"540.00000000\" "
          "color=\"#000000ff\" ts=\"0\" fn=\"\">left as drawn</text>\n"
          "</layer>\n"
          "</page>\n"
          "</xournal>\n";
  f.text = text.str();
  return f;
}

std::string gzip_bytes(const std::string& bytes) {
  z_stream z{};
  if (deflateInit2(&z, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
    throw std::runtime_error("deflateInit2");
  }
  std::string out(deflateBound(&z, bytes.size()), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  if (deflate(&z, Z_FINISH) != Z_STREAM_END) throw std::runtime_error("deflate");
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

} // namespace penshape::test
