// `penshape snap` on a page of 50 hand-drawn strokes (five generated strokes, tests/support/gen,
// ten times each, on a grid; the bench prints that its data is generated): the whole snap in this
// process (read, recognize with the ink certificate, write), and the `penshape snap --local`
// process as a user runs it, for an Inkscape SVG and a Xournal++ .xopp (and the SVG page drawn as
// Calligraphy outlines). Baseline beside it: the core recognizer alone on the same strokes' points
// (no file, no ink polygon). Target: the page in <= 1 s with
// --local.
//   build/release/bench/snap_bench [--runs N] [--cli PATH]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "penshape/core/recognize.hpp"
#include "snap/gzip.hpp"
#include "snap/snap_document.hpp"
#include "stroke_gen.hpp"

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

// The generated hand-drawn strokes the snap fixtures use too (tests/support/gen): circles, a
// rectangle, a triangle and a spiral (not a shape).
const std::pair<const char*, std::uint64_t> kGestures[] = {
    {"circle", 3}, {"rectangle", 4}, {"triangle", 5}, {"spiral", 2}, {"circle", 7}};

// A gesture's points scaled to a 100-unit box at (x0, y0).
std::vector<penshape::PointD> gesture(const std::pair<const char*, std::uint64_t>& which, double x0,
                                      double y0) {
  penshape::gen::StrokeGenerator generator(which.second);
  const penshape::gen::Drawing drawing = generator.draw(which.first);
  std::vector<penshape::PointD> pts;
  for (const auto& p : drawing.strokes.front().points) pts.push_back({p.x, p.y});
  double minx = 1e300, miny = 1e300, maxx = -1e300, maxy = -1e300;
  for (const auto& p : pts) {
    minx = std::min(minx, p.x), miny = std::min(miny, p.y);
    maxx = std::max(maxx, p.x), maxy = std::max(maxy, p.y);
  }
  const double s = 100 / std::max(maxx - minx, maxy - miny);
  for (auto& p : pts) p = {x0 + (p.x - minx) * s, y0 + (p.y - miny) * s};
  return pts;
}

std::vector<std::vector<penshape::PointD>> page_strokes() {
  std::vector<std::vector<penshape::PointD>> out;
  for (int i = 0; i < 50; ++i)
    out.push_back(gesture(kGestures[i % 5], 20 + 120 * (i % 10), 20 + 120 * (i / 10)));
  return out;
}

std::string coords(const std::vector<penshape::PointD>& pts, const char* sep) {
  std::ostringstream s;
  for (std::size_t i = 0; i < pts.size(); ++i) s << (i ? " " : "") << pts[i].x << sep << pts[i].y;
  return s.str();
}

std::string svg_page(const std::vector<std::vector<penshape::PointD>>& strokes) {
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" "
       "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\"1240\" "
       "height=\"640\">\n<g inkscape:groupmode=\"layer\" id=\"layer1\">\n";
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    s << "<path id=\"s" << i << "\" style=\"fill:none;stroke:#000;stroke-width:7\" d=\"M "
      << coords(strokes[i], ",") << "\"/>\n";
  }
  s << "</g>\n</svg>\n";
  return s.str();
}

// The same strokes as Calligraphy outlines (half-width 3.5): one edge forward, the other back.
std::string calligraphy_page(const std::vector<std::vector<penshape::PointD>>& strokes) {
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1240\" height=\"640\">\n";
  for (std::size_t k = 0; k < strokes.size(); ++k) {
    const auto& p = strokes[k];
    std::vector<penshape::PointD> left, right;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto a = p[i == 0 ? 0 : i - 1], b = p[std::min(i + 1, p.size() - 1)];
      const double len = std::max(1e-9, std::hypot(b.x - a.x, b.y - a.y));
      const double nx = -(b.y - a.y) / len * 3.5, ny = (b.x - a.x) / len * 3.5;
      left.push_back({p[i].x + nx, p[i].y + ny});
      right.push_back({p[i].x - nx, p[i].y - ny});
    }
    std::vector<penshape::PointD> ring(left);
    ring.insert(ring.end(), right.rbegin(), right.rend());
    s << "<path id=\"c" << k << "\" style=\"fill:#000;stroke:none\" d=\"M " << coords(ring, ",")
      << " Z\"/>\n";
  }
  s << "</svg>\n";
  return s.str();
}

std::string xopp_page(const std::vector<std::vector<penshape::PointD>>& strokes) {
  std::ostringstream s;
  s << "<?xml version=\"1.0\" standalone=\"no\"?>\n<xournal creator=\"Xournal++ 1.1.3\" "
       "fileversion=\"4\">\n<page width=\"1240\" height=\"640\">\n<background type=\"solid\" "
       "color=\"#ffffffff\" style=\"plain\"/>\n<layer>\n";
  for (const auto& st : strokes) {
    s << "<stroke tool=\"pen\" color=\"#000000ff\" width=\"5.67";
    for (std::size_t i = 0; i < st.size(); ++i)
      s << " " << 5.67 * (0.8 + 0.2 * std::sin(0.3 * static_cast<double>(i)));
    s << "\">" << coords(st, " ") << "</stroke>\n";
  }
  s << "</layer>\n</page>\n</xournal>\n";
  return s.str();
}

struct Row {
  std::string what;
  std::size_t snapped = 0;
  penshape::bench::Percentiles seconds;
};

Row library_row(const std::string& what, const std::string& bytes, int runs) {
  Row row{what, 0, {}};
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    const auto start = Clock::now();
    const auto result =
        penshape::snap::snap_document(bytes, {}, penshape::snap::recognize_page_in_process);
    t.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    row.snapped = result.replacements.size();
  }
  row.seconds = penshape::bench::percentiles(t);
  return row;
}

Row process_row(const std::string& what, const std::string& cli, const fs::path& in, int runs) {
  Row row{what, 0, {}};
  std::vector<double> t;
  const fs::path out = in.parent_path() / ("out-" + in.filename().string());
  const std::string cmd = cli + " snap --local " + in.string() + " " + out.string() + " 2>&1";
  for (int i = 0; i < runs; ++i) {
    const auto start = Clock::now();
    FILE* p = ::popen(cmd.c_str(), "r");
    if (p == nullptr) throw std::runtime_error("cannot run " + cmd);
    std::string text;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) text.append(buf, n);
    if (::pclose(p) != 0) throw std::runtime_error("failed: " + cmd + "\n" + text);
    t.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    // "penshape snap: N of M strokes snapped"
    const auto at = text.find("penshape snap: ");
    if (at != std::string::npos) row.snapped = std::stoul(text.substr(at + 15));
  }
  row.seconds = penshape::bench::percentiles(t);
  return row;
}

Row baseline_row(const std::vector<std::vector<penshape::PointD>>& strokes, int runs) {
  Row row{"baseline: core recognize() on the points only", 0, {}};
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    row.snapped = 0;
    const auto start = Clock::now();
    for (const auto& st : strokes) {
      std::vector<penshape::StrokePoint> pts;
      for (std::size_t k = 0; k < st.size(); ++k)
        pts.push_back({st[k].x, st[k].y, static_cast<double>(k)});
      penshape::RecognizerConfig config;
      config.pen_radius = 3.5;
      const auto r = penshape::recognize(pts, config);
      row.snapped += r.shape != penshape::ShapeClass::kFreeform ? 1 : 0;
    }
    t.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  row.seconds = penshape::bench::percentiles(t);
  return row;
}

} // namespace

int main(int argc, char** argv) {
  int runs = 9;
  std::string cli = PENSHAPE_CLI;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--runs") runs = std::max(1, std::atoi(argv[i + 1]));
    if (a == "--cli") cli = argv[i + 1];
  }
  const auto strokes = page_strokes();
  std::printf("data: generated strokes (tests/support/gen: circle, rectangle, triangle, spiral)\n");
  const std::string svg = svg_page(strokes), xopp = penshape::snap::gzip(xopp_page(strokes));
  const fs::path dir =
      fs::temp_directory_path() / ("penshape-snap-bench-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "page.svg") << svg;
  std::ofstream(dir / "page.xopp", std::ios::binary) << xopp;
  std::vector<Row> rows{
      library_row("SVG page, snap in this process (--local)", svg, runs),
      process_row("SVG page, `penshape snap --local` process", cli, dir / "page.svg", runs),
      library_row("SVG page as Calligraphy outlines, this process", calligraphy_page(strokes),
                  runs),
      library_row(".xopp page, snap in this process (--local)", xopp, runs),
      process_row(".xopp page, `penshape snap --local` process", cli, dir / "page.xopp", runs),
      baseline_row(strokes, runs),
  };
  fs::remove_all(dir);
  std::printf(
      "snap_bench: a page of %zu generated strokes (5 kinds x 10), %d runs each; target "
      "<= 1 s with --local\n\n",
      strokes.size(), runs);
  std::printf("| %-48s | %7s | %8s | %8s | %6s |\n", "what", "snapped", "p50 s", "max s", "<= 1 s");
  std::printf("|%s|%s|%s|%s|%s|\n", std::string(50, '-').c_str(), std::string(9, '-').c_str(),
              std::string(10, '-').c_str(), std::string(10, '-').c_str(),
              std::string(8, '-').c_str());
  for (const Row& r : rows) {
    std::printf("| %-48s | %4zu/50 | %8.3f | %8.3f | %6s |\n", r.what.c_str(), r.snapped,
                r.seconds.p50, r.seconds.max, r.seconds.max <= 1.0 ? "yes" : "NO");
  }
  return 0;
}
