// `penshape snap` on project-made documents (synthetic hand-like strokes, no outside data):
//  - a page of 50 shapes (circles, boxes, triangles drawn in one stroke, and squiggles) as an
//    Inkscape SVG, as Calligraphy outlines and as a Xournal++ .xopp: the whole snap in this
//    process and the `penshape snap --local` process; target: the page in <= 1 s;
//  - notes: P pages of 500 cursive words each (one pressure stroke per word, as Xournal++ writes
//    them; --pages 200 is 100k strokes, the default 20 is scaled up), snapped on one thread (the
//    baseline) and on every core;
//    targets: <= 1 ms of CPU per stroke, and 100k strokes in <= 30 s of wall time on 2 cores.
// The machine may be shared: compare rows of the same run, not runs of different days.
//   build/release/bench/snap_bench [--runs N] [--pages P] [--cli PATH]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_support.hpp"
#include "snap/gzip.hpp"
#include "snap/snap_document.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using penshape::PointD;
using Stroke = std::vector<PointD>;
namespace fs = std::filesystem;

// A shape drawn in one stroke in a 100-unit box at (x0, y0), with a hand's small wobble: a circle,
// a box, a triangle, or (k % 4 == 3) a squiggle that is no shape.
Stroke drawn_shape(int k, double x0, double y0, std::mt19937& rng) {
  std::normal_distribution<double> wobble(0.0, 0.6);
  Stroke out;
  const auto add = [&](double x, double y) { out.push_back({x + wobble(rng), y + wobble(rng)}); };
  const auto edge = [&](PointD a, PointD b) {
    for (int i = 0; i < 12; ++i) add(a.x + (b.x - a.x) * i / 12.0, a.y + (b.y - a.y) * i / 12.0);
  };
  switch (k % 4) {
    case 0:
      for (int i = 0; i <= 48; ++i)
        add(x0 + 50 + 45 * std::cos(i * M_PI / 24), y0 + 50 + 45 * std::sin(i * M_PI / 24));
      break;
    case 1:
      edge({x0, y0}, {x0 + 100, y0}), edge({x0 + 100, y0}, {x0 + 100, y0 + 70});
      edge({x0 + 100, y0 + 70}, {x0, y0 + 70}), edge({x0, y0 + 70}, {x0, y0});
      add(x0, y0);
      break;
    case 2:
      edge({x0 + 50, y0}, {x0 + 100, y0 + 90}), edge({x0 + 100, y0 + 90}, {x0, y0 + 90});
      edge({x0, y0 + 90}, {x0 + 50, y0});
      add(x0 + 50, y0);
      break;
    default:
      for (int i = 0; i <= 40; ++i)
        add(x0 + 2.5 * i, y0 + 50 + 30 * std::sin(i * 0.7) * std::cos(i * 0.23));
  }
  return out;
}

std::vector<Stroke> shapes_page() {
  std::mt19937 rng(29);
  std::vector<Stroke> out;
  out.reserve(50);
  for (int i = 0; i < 50; ++i) {
    const int row = i / 10;
    out.push_back(drawn_shape(i, 20.0 + 120 * (i % 10), 20.0 + 120.0 * row, rng));
  }
  return out;
}

// A cursive word of `letters` loops (a prolate cycloid, as a hand joins e's and l's) from x0 on
// the baseline y0.
Stroke cursive_word(double x0, double y0, int letters, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  Stroke out;
  const int n = 9 * letters;
  for (int i = 0; i <= n; ++i) {
    const double t = 2 * M_PI * i / 9.0;
    out.push_back({x0 + 1.2 * t - 2.5 * std::sin(t) + jitter(rng),
                   y0 - 3.5 * (1 - std::cos(t)) + jitter(rng)});
  }
  return out;
}

// One page of notes: 25 lines of 20 words.
std::vector<Stroke> notes_page(std::mt19937& rng) {
  std::uniform_int_distribution<int> letters(2, 6);
  std::vector<Stroke> out;
  for (int line = 0; line < 25; ++line) {
    double x = 40;
    for (int w = 0; w < 20; ++w) {
      const int n = letters(rng);
      out.push_back(cursive_word(x, 60 + 30.0 * line, n, rng));
      x += 7.54 * n + 4;
      if (x > 540) x = 40;
    }
  }
  return out;
}

std::string coords(const Stroke& pts, const char* sep) {
  std::ostringstream s;
  for (std::size_t i = 0; i < pts.size(); ++i) s << (i ? " " : "") << pts[i].x << sep << pts[i].y;
  return s.str();
}

std::string svg_page(const std::vector<Stroke>& strokes) {
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
std::string calligraphy_page(const std::vector<Stroke>& strokes) {
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1240\" height=\"640\">\n";
  for (std::size_t k = 0; k < strokes.size(); ++k) {
    const auto& p = strokes[k];
    Stroke left, right;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto a = p[i == 0 ? 0 : i - 1], b = p[std::min(i + 1, p.size() - 1)];
      const double len = std::max(1e-9, std::hypot(b.x - a.x, b.y - a.y));
      const double nx = -(b.y - a.y) / len * 3.5, ny = (b.x - a.x) / len * 3.5;
      left.push_back({p[i].x + nx, p[i].y + ny});
      right.push_back({p[i].x - nx, p[i].y - ny});
    }
    Stroke ring(left);
    ring.insert(ring.end(), right.rbegin(), right.rend());
    s << "<path id=\"c" << k << "\" style=\"fill:#000;stroke:none\" d=\"M " << coords(ring, ",")
      << " Z\"/>\n";
  }
  s << "</svg>\n";
  return s.str();
}

// A .xopp of the pages, each stroke with a pressure width per segment.
std::string xopp_pages(const std::vector<std::vector<Stroke>>& pages, double width) {
  std::ostringstream s;
  s << "<?xml version=\"1.0\" standalone=\"no\"?>\n<xournal creator=\"xournalpp 1.1.3\" "
       "fileversion=\"4\">\n";
  for (const auto& page : pages) {
    s << "<page width=\"1240\" height=\"842\">\n<background type=\"solid\" color=\"#ffffffff\" "
         "style=\"plain\"/>\n<layer>\n";
    for (const auto& st : page) {
      s << "<stroke tool=\"pen\" color=\"#000000ff\" width=\"" << width;
      for (std::size_t i = 0; i + 1 < st.size(); ++i)
        s << " " << width * (0.8 + 0.2 * std::sin(0.3 * static_cast<double>(i)));
      s << "\">" << coords(st, " ") << "</stroke>\n";
    }
    s << "</layer>\n</page>\n";
  }
  s << "</xournal>\n";
  return s.str();
}

struct Row {
  std::string what;
  std::size_t strokes = 0, snapped = 0;
  double wall = 0, cpu = 0; // seconds (the median run's for pages)
};

Row library_row(const std::string& what, const std::string& bytes, int runs, std::size_t threads) {
  Row row{what, 0, 0, 0, 0};
  std::vector<double> wall, cpu;
  penshape::snap::SnapOptions options;
  options.threads = threads;
  for (int i = 0; i < runs; ++i) {
    const double cpu0 = penshape::bench::process_usage().cpu_seconds;
    const auto start = Clock::now();
    const auto result =
        penshape::snap::snap_document(bytes, options, penshape::snap::recognize_page_in_process);
    wall.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    cpu.push_back(penshape::bench::process_usage().cpu_seconds - cpu0);
    row.snapped = result.replacements.size();
    row.strokes = result.strokes;
  }
  row.wall = penshape::bench::percentiles(wall).p50;
  row.cpu = penshape::bench::percentiles(cpu).p50;
  return row;
}

Row process_row(const std::string& what, const std::string& cli, const fs::path& in, int runs) {
  Row row{what, 50, 0, 0, 0};
  std::vector<double> t;
  const fs::path out = in.parent_path() / ("out-" + in.filename().string());
  const std::string cmd =
      cli + " snap --local --quiet " + in.string() + " " + out.string() + " 2>&1";
  for (int i = 0; i < runs; ++i) {
    const auto start = Clock::now();
    FILE* p = ::popen(cmd.c_str(), "r");
    if (p == nullptr) throw std::runtime_error("cannot run " + cmd);
    std::string text;
    char buf[4096];
    for (std::size_t n = std::fread(buf, 1, sizeof buf, p); n > 0;
         n = std::fread(buf, 1, sizeof buf, p)) {
      text.append(buf, n);
    }
    if (::pclose(p) != 0) throw std::runtime_error("failed: " + cmd + "\n" += text);
    t.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    // "penshape snap: N of M strokes snapped"
    const auto at = text.find("penshape snap: ");
    if (at != std::string::npos) row.snapped = std::stoul(text.substr(at + 15));
  }
  row.wall = penshape::bench::percentiles(t).p50;
  row.cpu = -1; // not measured for a child process
  return row;
}

void print(const std::vector<Row>& rows) {
  std::printf("| %-52s | %7s | %7s | %8s | %9s |\n", "what", "strokes", "snapped", "wall s",
              "CPU ms/st");
  std::printf("|%s|%s|%s|%s|%s|\n", std::string(54, '-').c_str(), std::string(9, '-').c_str(),
              std::string(9, '-').c_str(), std::string(10, '-').c_str(),
              std::string(11, '-').c_str());
  for (const Row& r : rows) {
    const double per =
        r.cpu >= 0 && r.strokes > 0 ? 1e3 * r.cpu / static_cast<double>(r.strokes) : 0;
    const std::string cpu = r.cpu >= 0 ? std::to_string(per).substr(0, 5) : "-";
    std::printf("| %-52s | %7zu | %7zu | %8.3f | %9s |\n", r.what.c_str(), r.strokes, r.snapped,
                r.wall, cpu.c_str());
  }
}

} // namespace

int main(int argc, char** argv) {
  int runs = 5, pages = 20;
  std::string cli = PENSHAPE_CLI;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--runs") runs = std::max(1, std::atoi(argv[i + 1]));
    if (a == "--pages") pages = std::max(1, std::atoi(argv[i + 1]));
    if (a == "--cli") cli = argv[i + 1];
  }
  const auto shapes = shapes_page();
  const std::string svg = svg_page(shapes), xopp = penshape::snap::gzip(xopp_pages({shapes}, 5.67));
  const fs::path dir =
      fs::temp_directory_path() / ("penshape-snap-bench-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "page.svg") << svg;
  std::ofstream(dir / "page.xopp", std::ios::binary) << xopp;
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  std::printf(
      "snap_bench: %d runs of a 50-shape page (medians); notes: %d pages x 500 words, "
      "once; %zu cores\n\n",
      runs, pages, cores);
  print({library_row("shapes page, SVG, this process, all cores", svg, runs, 0),
         process_row("shapes page, SVG, `penshape snap --local` process", cli, dir / "page.svg",
                     runs),
         library_row("shapes page as Calligraphy outlines, this process", calligraphy_page(shapes),
                     runs, 0),
         library_row("shapes page, .xopp, this process, all cores", xopp, runs, 0),
         process_row("shapes page, .xopp, `penshape snap --local` process", cli, dir / "page.xopp",
                     runs)});
  fs::remove_all(dir);
  std::mt19937 rng(29);
  std::vector<std::vector<Stroke>> notes;
  notes.reserve(static_cast<std::size_t>(pages));
  for (int p = 0; p < pages; ++p) notes.push_back(notes_page(rng));
  const std::string notes_xopp = penshape::snap::gzip(xopp_pages(notes, 1.41));
  std::printf("\nnotes (targets: <= 1 ms CPU per stroke; 100k strokes in <= 30 s on 2 cores):\n\n");
  const Row one = library_row("notes .xopp, 1 thread (baseline)", notes_xopp, 1, 1);
  const Row all = library_row("notes .xopp, all cores", notes_xopp, 1, 0);
  print({one, all});
  const double per_100k =
      all.wall * 1e5 / static_cast<double>(std::max<std::size_t>(1, all.strokes));
  std::printf(
      "\nall cores: %.1f s for 100k strokes (scaled), speed-up %.2fx over 1 thread; "
      "targets %s / %s\n",
      per_100k, one.wall / std::max(1e-9, all.wall),
      1e3 * all.cpu / static_cast<double>(std::max<std::size_t>(1, all.strokes)) <= 1.0
          ? "CPU met"
          : "CPU NOT met",
      per_100k <= 30 ? "wall met" : "wall NOT met");
  return 0;
}
