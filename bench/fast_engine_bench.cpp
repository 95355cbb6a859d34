// Micro-benchmark of the fast deconstruction engine alone: kazakhstan_paper1881, eps = r/2,
// delta = eps/8, r = w/10, w/30, w/50, w/100 (w = bounding-box width). Prints a table of the
// median time per decision, the answer and |P|; `--json` prints one object per case.
// `--engines both` also times the reference engine on each case, interleaved in the same run,
// and prints each engine's CPU time against the fast engine's (the baseline; the former
// double-with-margins comparisons are gone from the engine, issue 22). The default,
// `--engines fast`, times the fast engine alone; deconstruct_bench has the full comparison.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench_data.hpp"
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
  std::string engines = "fast";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--json") json = true;
    if (a == "--repeats" && i + 1 < argc) repeats = std::max(1, std::atoi(argv[++i]));
    if (a == "--engines" && i + 1 < argc) engines = argv[++i];
  }
  const std::string file =
      penshape::bench::shared_data_dir() + "/polygons/kazakhstan_paper1881.txt";
  penshape::bench::say_data("fast_engine_bench", file + " (the paper's polygon)");
  const penshape::PolygonSet q = read_polygon(file);
  penshape::Rational min_x = q.polygons[0].outer[0].x, max_x = min_x;
  for (const auto& p : q.polygons[0].outer) {
    min_x = std::min(min_x, p.x);
    max_x = std::max(max_x, p.x);
  }
  const penshape::Rational w = max_x - min_x;
  using Decide = penshape::DeconstructResult (*)(
      const penshape::PolygonSet&, const penshape::DeconstructParams&, const penshape::CancelHook&,
      const penshape::DeconstructLimits&);
  const Decide fast = [](const penshape::PolygonSet& set, const penshape::DeconstructParams& p,
                         const penshape::CancelHook& c, const penshape::DeconstructLimits& l) {
    return penshape::detail::decide_fast(set, p, c, l);
  };
  std::vector<std::pair<const char*, Decide>> modes{{"fast", fast}};
  if (engines == "both") modes.push_back({"reference", &penshape::detail::decide_reference});
  if (!json) {
    std::printf("%-8s %-9s %-10s %12s %12s %12s %8s %6s %8s\n", "r", "engine", "answer",
                "median_ms", "min_ms", "cpu_med_ms", "|P|", "disk", "cpu/fast");
  }
  for (const int div : {10, 30, 50, 100}) {
    penshape::DeconstructParams params;
    params.radius = w / div;
    params.tolerance = params.radius / 2;
    params.precision = params.tolerance / 8;
    const std::string r = "w/" + std::to_string(div);
    // Interleaved repeats, so that load on the shared machine hits both engines alike.
    std::vector<std::vector<double>> ms(modes.size()), cpu(modes.size());
    std::vector<penshape::DeconstructResult> last(modes.size());
    for (int k = 0; k < repeats; ++k) {
      for (std::size_t m = 0; m < modes.size(); ++m) {
        const double c0 = cpu_ms();
        const auto t0 = std::chrono::steady_clock::now();
        last[m] = modes[m].second(q, params, {}, {});
        const auto t1 = std::chrono::steady_clock::now();
        cpu[m].push_back(cpu_ms() - c0);
        ms[m].push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      }
    }
    std::vector<double> cpu_median(modes.size());
    for (std::size_t m = 0; m < modes.size(); ++m) {
      std::sort(ms[m].begin(), ms[m].end());
      std::sort(cpu[m].begin(), cpu[m].end());
      cpu_median[m] = cpu[m][cpu[m].size() / 2];
    }
    for (std::size_t m = 0; m < modes.size(); ++m) {
      const double median = ms[m][ms[m].size() / 2];
      const double ratio = cpu_median[m] / cpu_median.front();
      if (json) {
        std::printf(
            "{\"case\":\"kazakhstan_paper1881\",\"r\":\"%s\",\"engine\":\"%s\",\"answer\":\"%s\","
            "\"median_ms\":%.3f,\"min_ms\":%.3f,"
            "\"cpu_median_ms\":%.3f,\"solution_vertices\":%zu,\"disk_vertices\":%zu}\n",
            r.c_str(), modes[m].first, answer_name(last[m].answer), median, ms[m].front(),
            cpu_median[m], last[m].solution.vertex_count(), last[m].disk_vertices);
      } else {
        std::printf("%-8s %-9s %-10s %12.3f %12.3f %12.3f %8zu %6zu %7.2fx\n", r.c_str(),
                    modes[m].first, answer_name(last[m].answer), median, ms[m].front(),
                    cpu_median[m], last[m].solution.vertex_count(), last[m].disk_vertices, ratio);
      }
    }
  }
  return 0;
}
