// Micro-benchmark of the fast deconstruction engine alone: kazakhstan_paper1881, eps = r/2,
// delta = eps/8, r = w/10, w/30, w/50, w/100 (w = bounding-box width). Prints a table of the
// median time per decision, the answer and |P|; `--json` prints one object per case.
// The side-by-side comparison with the reference engine lives in the main deconstruct bench.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "engine/engines.hpp"

namespace {

// Thread CPU time: robust against other processes on a shared machine.
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) / 1e6;
}

penshape::PolygonSet read_polygon(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "cannot open %s\n", path.c_str());
    std::exit(2);
  }
  penshape::PolygonWithHoles poly;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    double x = 0, y = 0;
    if (ls >> x >> y) poly.outer.push_back(penshape::exact(penshape::PointD{x, y}));
  }
  penshape::PolygonSet set;
  set.polygons.push_back(std::move(poly));
  penshape::normalize_orientation(set);
  return set;
}

const char* answer_name(penshape::Answer a) {
  switch (a) {
    case penshape::Answer::kYes:
      return "YES";
    case penshape::Answer::kNo:
      return "NO";
    default:
      return "UNDECIDED";
  }
}

} // namespace

int main(int argc, char** argv) {
  bool json = false;
  int repeats = 9;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--json") json = true;
    if (a == "--repeats" && i + 1 < argc) repeats = std::max(1, std::atoi(argv[++i]));
  }
  const char* env = std::getenv("PENSHAPE_SHARED_DATA_DIR");
  const std::string dir = env != nullptr ? env : PENSHAPE_SHARED_DATA_DIR;
  const penshape::PolygonSet q = read_polygon(dir + "/polygons/kazakhstan_paper1881.txt");
  penshape::Rational min_x = q.polygons[0].outer[0].x, max_x = min_x;
  for (const auto& p : q.polygons[0].outer) {
    min_x = std::min(min_x, p.x);
    max_x = std::max(max_x, p.x);
  }
  const penshape::Rational w = max_x - min_x;
  if (!json) {
    std::printf("%-8s %-10s %12s %12s %12s %8s %6s\n", "r", "answer", "median_ms", "min_ms",
                "cpu_med_ms", "|P|", "disk");
  }
  for (const int div : {10, 30, 50, 100}) {
    penshape::DeconstructParams params;
    params.radius = w / div;
    params.tolerance = params.radius / 2;
    params.precision = params.tolerance / 8;
    std::vector<double> ms, cpu;
    penshape::DeconstructResult last;
    for (int k = 0; k < repeats; ++k) {
      const double c0 = cpu_ms();
      const auto t0 = std::chrono::steady_clock::now();
      last = penshape::detail::decide_fast(q, params, {}, {});
      const auto t1 = std::chrono::steady_clock::now();
      cpu.push_back(cpu_ms() - c0);
      ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    std::sort(ms.begin(), ms.end());
    std::sort(cpu.begin(), cpu.end());
    const double median = ms[ms.size() / 2];
    const double cpu_median = cpu[cpu.size() / 2];
    const std::string r = "w/" + std::to_string(div);
    if (json) {
      std::printf(
          "{\"case\":\"kazakhstan_paper1881\",\"r\":\"%s\",\"engine\":\"fast\",\"answer\":\"%s\","
          "\"median_ms\":%.3f,\"min_ms\":%.3f,\"cpu_median_ms\":%.3f,\"solution_vertices\":%zu,"
          "\"disk_vertices\":%zu}\n",
          r.c_str(), answer_name(last.answer), median, ms.front(), cpu_median,
          last.solution.vertex_count(), last.disk_vertices);
    } else {
      std::printf("%-8s %-10s %12.3f %12.3f %12.3f %8zu %6zu\n", r.c_str(),
                  answer_name(last.answer), median, ms.front(), cpu_median,
                  last.solution.vertex_count(), last.disk_vertices);
    }
  }
  return 0;
}
