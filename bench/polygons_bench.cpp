// The default engine on every polygon of ../shared/data/polygons, nine decisions each: r = w/10,
// w/30, w/50 (w the bounding box's width) times eps = r/4, r/2, 3r/4, delta = eps/8. Each
// decision runs N times with Clipper's sweep as the engine turns it (wide offset paths a quarter
// turn, stripe_union.hpp) and N times with the paths as given, alternated; the table prints the
// sums of the median thread CPU times per polygon, both ways, and the nine answers (which must
// agree: the turn changes only candidates).
//
//   polygons_bench [--runs N] [--data DIR]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench_data.hpp"
#include "bench_support.hpp"
#include "engine/fast/clipper_stage.hpp"
#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_io.hpp"

namespace {

using penshape::Rational;

std::vector<std::string> polygon_files(const std::string& dir) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    if (e.path().extension() == ".txt") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

Rational width(const penshape::PolygonSet& q) {
  Rational lo = q.polygons[0].outer[0].x, hi = lo;
  for (const auto& poly : q.polygons) {
    for (const auto& v : poly.outer) {
      lo = std::min(lo, v.x);
      hi = std::max(hi, v.x);
    }
  }
  return hi - lo;
}

// One decision's thread CPU seconds, the sweep turned or not.
double timed(const penshape::PolygonSet& q, const penshape::DeconstructParams& p, bool turn,
             penshape::Answer& answer) {
  penshape::fast::set_turn_wide_paths(turn);
  const double c0 = penshape::bench::thread_cpu_seconds();
  answer = penshape::deconstruct(q, p).answer;
  return penshape::bench::thread_cpu_seconds() - c0;
}

struct Row {
  double turned = 0, upright = 0;
  std::string answers;
  bool same = true;
};

Row measure(const penshape::PolygonSet& q, int runs) {
  Row row;
  const Rational w = width(q);
  for (const int divisor : {10, 30, 50}) {
    for (const int quarters : {1, 2, 3}) {
      const Rational r = w / divisor, eps = r * quarters / 4;
      const penshape::DeconstructParams p{r, eps, eps / 8, penshape::EngineKind::kFast};
      std::vector<double> turned, upright;
      penshape::Answer a = penshape::Answer::kUndecided, b = a;
      for (int i = 0; i < runs; ++i) {
        upright.push_back(timed(q, p, false, b));
        turned.push_back(timed(q, p, true, a));
      }
      row.turned += penshape::bench::median_of(turned);
      row.upright += penshape::bench::median_of(upright);
      row.answers += penshape::to_string(a)[0];
      row.same = row.same && a == b;
    }
  }
  return row;
}

} // namespace

int main(int argc, char** argv) {
  int runs = 3;
  std::string data = penshape::bench::shared_data_dir();
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--data" && i + 1 < argc) {
      data = argv[++i];
    } else {
      std::fprintf(stderr, "usage: polygons_bench [--runs N] [--data DIR]\n");
      return 2;
    }
  }
  penshape::bench::say_data("polygons_bench", data + "/polygons");
  std::printf(
      "nine decisions per polygon (r = w/10, w/30, w/50; eps = r/4, r/2, 3r/4), sum of "
      "median thread CPU ms of %d runs\n%-32s %8s | %10s %10s %7s | %s\n",
      runs, "polygon", "vertices", "as given", "turned", "change", "answers");
  double all_turned = 0, all_upright = 0;
  bool all_same = true;
  for (const std::string& file : polygon_files(data + "/polygons")) {
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    penshape::PolygonSet q;
    try {
      q = penshape::read_polygon_text(text.str());
    } catch (const std::exception&) {
      continue; // not a polygon file
    }
    if (q.polygons.empty()) continue;
    const Row row = measure(q, runs);
    all_turned += row.turned;
    all_upright += row.upright;
    all_same = all_same && row.same;
    std::printf("%-32s %8zu | %10.2f %10.2f %+6.1f%% | %s%s\n",
                std::filesystem::path(file).stem().c_str(), q.vertex_count(), row.upright * 1e3,
                row.turned * 1e3, 100.0 * (row.turned / row.upright - 1.0), row.answers.c_str(),
                row.same ? "" : "  (answers differ)");
  }
  std::printf("%-41s | %10.2f %10.2f %+6.1f%% | %s\n", "all", all_upright * 1e3, all_turned * 1e3,
              all_upright > 0 ? 100.0 * (all_turned / all_upright - 1.0) : 0.0,
              all_same ? "the same answers" : "ANSWERS DIFFER");
  return all_same ? 0 : 1;
}
