// Live recognizer cost per sample over the shared $1 gesture logs (subjects s01..s06, all
// speeds), the previous refit policy (kEager, the baseline) beside the bounded one (kBounded)
// in the same run.
//
// Streams:
//   $1 as logged   the samples as the logs hold them (about 60-130 per stroke);
//   $1 at 1 kHz    every 8th stroke, linearly interpolated to one sample per millisecond of
//                  its time stamps: the daemon's stream from a 1 kHz tablet.
// Per policy and stream: add() CPU time per call (p50, p99, max, mean), add() total per stroke
// (p50, p99, max), finish() per stroke (p50, p99, max), and, independent of timing, how many
// circles/rectangles/triangles had a non-freeform preview at 80% of their samples and how many
// strokes finish() classified as recognize() does. Times are the thread's CPU time (the
// machine is shared; wall-clock tails would include time the thread was not running).
//
// Usage: live_recognizer_bench [--json]   (data dir: $PENSHAPE_SHARED_DATA_DIR)
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "bench_data.hpp"
#include "dollar_xml.hpp"
#include "penshape/core/live_recognizer.hpp"
#include "penshape/core/recognize.hpp"

namespace {

using penshape::ShapeClass;
using penshape::StrokePoint;

double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

struct Stroke {
  std::string kind; // gesture name without digits
  std::vector<StrokePoint> points;
  ShapeClass offline = ShapeClass::kFreeform; // recognize() on the whole stroke
};

std::vector<Stroke> load_strokes(const std::filesystem::path& root) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (e.is_regular_file() && e.path().extension() == ".xml") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<Stroke> out;
  for (const auto& f : files) {
    penshape::dollar::Gesture g = penshape::dollar::read_dollar_xml(f);
    Stroke s;
    s.kind = g.kind();
    s.points = std::move(g.points);
    out.push_back(std::move(s));
  }
  return out;
}

// One sample per millisecond between the first and last time stamps, linearly interpolated.
std::vector<StrokePoint> at_1khz(const std::vector<StrokePoint>& in) {
  std::vector<StrokePoint> out;
  if (in.size() < 2) return in;
  const double t0 = in.front().t, t1 = in.back().t;
  std::size_t j = 0;
  for (double t = t0; t <= t1; t += 1e-3) {
    while (j + 2 < in.size() && in[j + 1].t < t) ++j;
    const StrokePoint& a = in[j];
    const StrokePoint& b = in[j + 1];
    const double f = b.t > a.t ? std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0) : 1.0;
    out.push_back({a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), t});
  }
  out.push_back(in.back());
  return out;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto i = static_cast<std::size_t>(std::lround(q * static_cast<double>(v.size() - 1)));
  return v[std::min(i, v.size() - 1)];
}

struct Result {
  std::string stream, policy;
  std::vector<double> add_ms, stroke_ms, finish_ms;
  std::size_t shapes = 0, previewed_at_80 = 0, strokes = 0, agree = 0, refits = 0;
};

Result run(const std::vector<Stroke>& strokes, const std::string& stream,
           penshape::RefitPolicy policy) {
  Result r;
  r.stream = stream;
  r.policy = policy == penshape::RefitPolicy::kEager ? "old: eager" : "new: bounded";
  penshape::LiveOptions options;
  options.policy = policy;
  penshape::LiveRecognizer live({}, options);
  for (const Stroke& s : strokes) {
    const std::size_t at_80 = (s.points.size() * 4) / 5;
    bool previewed = false;
    double total = 0.0;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const double c = cpu_ms();
      live.add(s.points[i]);
      const double dt = cpu_ms() - c;
      r.add_ms.push_back(dt);
      total += dt;
      if (i + 1 == at_80) previewed = live.preview().shape != ShapeClass::kFreeform;
    }
    r.stroke_ms.push_back(total);
    r.refits += live.stats().refits;
    const double c = cpu_ms();
    const penshape::Recognition rec = live.finish();
    r.finish_ms.push_back(cpu_ms() - c);
    ++r.strokes;
    if (rec.shape == s.offline) ++r.agree;
    if (s.kind == "circle" || s.kind == "rectangle" || s.kind == "triangle") {
      ++r.shapes;
      if (previewed) ++r.previewed_at_80;
    }
  }
  return r;
}

} // namespace

int main(int argc, char** argv) {
  bool json = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--json") == 0) {
      json = true;
    } else {
      std::fprintf(stderr, "usage: live_recognizer_bench [--json]\n");
      return 2;
    }
  }
  const std::filesystem::path data = penshape::bench::shared_data_dir();
  penshape::bench::say_data("live_recognizer_bench", (data / "strokes" / "dollar1").string());
  std::vector<Stroke> logged = load_strokes(data / "strokes" / "dollar1");
  if (logged.empty()) {
    std::fprintf(stderr, "live_recognizer_bench: no $1 logs under %s\n", data.string().c_str());
    return 2;
  }
  std::vector<Stroke> khz;
  for (std::size_t i = 0; i < logged.size(); i += 8) {
    Stroke s = logged[i];
    s.points = at_1khz(s.points);
    khz.push_back(std::move(s));
  }
  for (auto* set : {&logged, &khz}) {
    for (Stroke& s : *set) s.offline = penshape::recognize(s.points).shape;
  }
  std::vector<Result> results;
  for (const auto& [set, name] : {std::pair{&logged, "$1 as logged"}, {&khz, "$1 at 1 kHz"}}) {
    results.push_back(run(*set, name, penshape::RefitPolicy::kEager));
    results.push_back(run(*set, name, penshape::RefitPolicy::kBounded));
  }
  if (!json) {
    std::printf(
        "live recognizer: CPU ms per add() and per stroke; previews at 80%% of the\n"
        "samples of circles/rectangles/triangles; finish() == recognize() class\n");
    std::printf("%-13s %-13s %7s %8s %8s %8s %8s | %8s %8s %8s | %7s %7s %7s | %9s %11s %7s\n",
                "stream", "policy", "adds", "add p50", "add p99", "add max", "add mean", "strk p50",
                "strk p99", "strk max", "fin p50", "fin p99", "fin max", "preview", "agree",
                "refits");
  }
  for (const Result& r : results) {
    const double mean = std::accumulate(r.add_ms.begin(), r.add_ms.end(), 0.0) /
                        static_cast<double>(r.add_ms.size());
    const double refits = static_cast<double>(r.refits) / static_cast<double>(r.strokes);
    if (json) {
      std::printf(
          "{\"stream\":\"%s\",\"policy\":\"%s\",\"adds\":%zu,\"add_p50_ms\":%.5f,"
          "\"add_p99_ms\":%.5f,\"add_max_ms\":%.4f,\"add_mean_ms\":%.5f,"
          "\"stroke_p50_ms\":%.4f,\"stroke_p99_ms\":%.4f,\"stroke_max_ms\":%.4f,"
          "\"finish_p50_ms\":%.4f,\"finish_p99_ms\":%.4f,\"finish_max_ms\":%.4f,"
          "\"shapes\":%zu,\"previewed_at_80\":%zu,\"strokes\":%zu,\"agree\":%zu,"
          "\"refits_per_stroke\":%.2f}\n",
          r.stream.c_str(), r.policy.c_str(), r.add_ms.size(), percentile(r.add_ms, 0.5),
          percentile(r.add_ms, 0.99), percentile(r.add_ms, 1.0), mean, percentile(r.stroke_ms, 0.5),
          percentile(r.stroke_ms, 0.99), percentile(r.stroke_ms, 1.0), percentile(r.finish_ms, 0.5),
          percentile(r.finish_ms, 0.99), percentile(r.finish_ms, 1.0), r.shapes, r.previewed_at_80,
          r.strokes, r.agree, refits);
    } else {
      std::printf(
          "%-13s %-13s %7zu %8.4f %8.4f %8.3f %8.4f | %8.3f %8.3f %8.3f | %7.3f %7.3f "
          "%7.3f | %4zu/%-4zu %5zu/%-5zu %7.2f\n",
          r.stream.c_str(), r.policy.c_str(), r.add_ms.size(), percentile(r.add_ms, 0.5),
          percentile(r.add_ms, 0.99), percentile(r.add_ms, 1.0), mean, percentile(r.stroke_ms, 0.5),
          percentile(r.stroke_ms, 0.99), percentile(r.stroke_ms, 1.0), percentile(r.finish_ms, 0.5),
          percentile(r.finish_ms, 0.99), percentile(r.finish_ms, 1.0), r.previewed_at_80, r.shapes,
          r.agree, r.strokes, refits);
    }
  }
  return 0;
}
