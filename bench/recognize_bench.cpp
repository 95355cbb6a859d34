// Recognition time per stroke over the shared $1 gesture logs (subjects s01..s06, all speeds).
//
// Cases, side by side in one run:
//   recognize (offline)   recognize() on the whole stroke: the baseline, what a client pays
//                         when it submits a finished stroke;
//   live: pen-up          LiveRecognizer::finish() after the samples were fed one by one: the
//                         pen-up latency of the live path, which reuses surviving fits;
//   live: per sample      LiveRecognizer::add() per sample (refits included where they happen);
//   ink polygon           ink_polygon() of the stroke with the recognizer's pen radius (what the
//                         daemon computes anyway; context for the next row, not part of it);
//   recognize + ink cert  recognize(StrokeInput) with that ink polygon: the path screening plus
//                         the ink-level certificate of the screened candidates (the daemon's
//                         pen-up path), beside the path-certified baseline in the first row.
// Each time is measured twice: wall clock and the thread's CPU time (the machine is shared, so
// wall-clock tails include time the thread was not running). Target: p99 <= 5 ms per stroke.
//
// Usage: recognize_bench [--json] [--repeat N]   (data dir: $PENSHAPE_SHARED_DATA_DIR)
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "penshape/core/ink.hpp"
#include "penshape/core/live_recognizer.hpp"
#include "penshape/core/recognize.hpp"

namespace {

using penshape::StrokePoint;

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::vector<std::vector<StrokePoint>> load_strokes(const std::filesystem::path& root) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (e.is_regular_file() && e.path().extension() == ".xml") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  const std::regex point("<Point X=\"(-?[0-9.]+)\" Y=\"(-?[0-9.]+)\" T=\"(-?[0-9.]+)\"");
  std::vector<std::vector<StrokePoint>> out;
  for (const auto& f : files) {
    std::ifstream in(f);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    std::vector<StrokePoint> pts;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), point);
         it != std::sregex_iterator(); ++it) {
      pts.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]) / 1000.0});
    }
    out.push_back(std::move(pts));
  }
  return out;
}

struct Series {
  std::string name;
  std::vector<double> wall_ms;
  std::vector<double> cpu_ms;
};

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto i = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5);
  return v[std::min(i, v.size() - 1)];
}

} // namespace

int main(int argc, char** argv) {
  bool json = false;
  int repeat = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--json") == 0) {
      json = true;
    } else if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else {
      std::fprintf(stderr, "usage: recognize_bench [--json] [--repeat N]\n");
      return 2;
    }
  }
  const char* env = std::getenv("PENSHAPE_SHARED_DATA_DIR");
  const std::filesystem::path data = env ? env : PENSHAPE_SHARED_DATA_DIR;
  const auto strokes = load_strokes(data / "strokes" / "dollar1");
  if (strokes.empty()) {
    std::fprintf(stderr, "recognize_bench: no $1 logs under %s\n", data.string().c_str());
    return 2;
  }
  Series offline{"recognize (offline)", {}, {}};
  Series pen_up{"live: pen-up", {}, {}};
  Series per_sample{"live: per sample", {}, {}};
  Series ink_build{"ink polygon", {}, {}};
  Series ink_cert{"recognize + ink cert", {}, {}};
  std::size_t snaps = 0, ink_snaps = 0;
  penshape::LiveRecognizer live;
  for (int r = 0; r < repeat; ++r) {
    for (const auto& s : strokes) {
      double w = wall_seconds(), c = thread_cpu_seconds();
      const penshape::Recognition rec = penshape::recognize(s);
      offline.wall_ms.push_back((wall_seconds() - w) * 1e3);
      offline.cpu_ms.push_back((thread_cpu_seconds() - c) * 1e3);
      if (rec.shape != penshape::ShapeClass::kFreeform) ++snaps;

      for (const StrokePoint& p : s) {
        w = wall_seconds();
        c = thread_cpu_seconds();
        live.add(p);
        per_sample.wall_ms.push_back((wall_seconds() - w) * 1e3);
        per_sample.cpu_ms.push_back((thread_cpu_seconds() - c) * 1e3);
      }
      w = wall_seconds();
      c = thread_cpu_seconds();
      (void)live.finish();
      pen_up.wall_ms.push_back((wall_seconds() - w) * 1e3);
      pen_up.cpu_ms.push_back((thread_cpu_seconds() - c) * 1e3);

      // The ink polygon with the pen radius the recognizer uses, then the ink-certified run.
      const penshape::ToleranceChoice tol = penshape::choose_tolerance(s, {});
      std::vector<penshape::InkSample> ink_samples;
      for (const StrokePoint& p : s) ink_samples.push_back({p.x, p.y, tol.pen_radius});
      penshape::InkOptions options;
      options.radius_mm = tol.pen_radius;
      w = wall_seconds();
      c = thread_cpu_seconds();
      const penshape::InkPolygon ink = penshape::ink_polygon(ink_samples, options);
      ink_build.wall_ms.push_back((wall_seconds() - w) * 1e3);
      ink_build.cpu_ms.push_back((thread_cpu_seconds() - c) * 1e3);
      penshape::StrokeInput input;
      input.samples = s;
      input.ink = &ink;
      w = wall_seconds();
      c = thread_cpu_seconds();
      const penshape::Recognition with_ink = penshape::recognize(input);
      ink_cert.wall_ms.push_back((wall_seconds() - w) * 1e3);
      ink_cert.cpu_ms.push_back((thread_cpu_seconds() - c) * 1e3);
      if (with_ink.shape != penshape::ShapeClass::kFreeform) ++ink_snaps;
    }
  }
  const Series* all[] = {&offline, &pen_up, &per_sample, &ink_build, &ink_cert};
  if (!json) {
    std::printf(
        "recognition over %zu $1 strokes x %d (snaps per pass: %zu path-certified, %zu "
        "ink-certified); times in ms\n",
        strokes.size(), repeat, snaps / static_cast<std::size_t>(repeat),
        ink_snaps / static_cast<std::size_t>(repeat));
    std::printf("%-22s %8s %9s %9s %9s %9s %9s %9s\n", "case", "n", "p50 cpu", "p99 cpu", "max cpu",
                "p50 wall", "p99 wall", "target");
  }
  for (const Series* s : all) {
    const double p50c = percentile(s->cpu_ms, 0.5), p99c = percentile(s->cpu_ms, 0.99);
    const double maxc = percentile(s->cpu_ms, 1.0);
    const double p50w = percentile(s->wall_ms, 0.5), p99w = percentile(s->wall_ms, 0.99);
    const bool per_stroke = s != &per_sample && s != &ink_build;
    if (json) {
      std::printf(
          "{\"case\":\"%s\",\"n\":%zu,\"p50_cpu_ms\":%.4f,\"p99_cpu_ms\":%.4f,"
          "\"max_cpu_ms\":%.4f,\"p50_wall_ms\":%.4f,\"p99_wall_ms\":%.4f,"
          "\"target_p99_ms\":%s}\n",
          s->name.c_str(), s->cpu_ms.size(), p50c, p99c, maxc, p50w, p99w,
          per_stroke ? "5" : "null");
    } else {
      std::printf("%-22s %8zu %9.3f %9.3f %9.3f %9.3f %9.3f %9s\n", s->name.c_str(),
                  s->cpu_ms.size(), p50c, p99c, maxc, p50w, p99w, per_stroke ? "p99<=5" : "-");
    }
  }
  return 0;
}
