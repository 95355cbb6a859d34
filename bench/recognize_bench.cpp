// Recognition time per stroke over the shared $1 gesture logs (subjects s01..s06, all speeds),
// at two densities:
//   $1 as logged   the samples as the logs hold them (about 100-450 per stroke);
//   $1 at 1 kHz    every --khz-stride'th stroke (default 4), linearly interpolated by time to
//                  one sample per millisecond between its first and last time stamps (what a
//                  1 kHz tablet delivers: thousands of samples per stroke).
//
// Cases per density, side by side in one run:
//   recognize, unthinned  recognize() with thin_tolerance_fraction = 0: the previous path (every
//                         sample certified, linear scans), the baseline;
//   recognize (offline)   recognize() with the defaults (thinned within epsilon / 50, segment
//                         grid): what a client pays when it submits a finished stroke;
//   live: pen-up          LiveRecognizer::finish() after the samples were fed one by one: the
//                         pen-up latency of the live path, which reuses surviving fits;
//   live: pen-up unthin.  the same with thin_tolerance_fraction = 0 (baseline);
//   live: per sample      LiveRecognizer::add() per sample (refits included where they happen);
//   ink polygon           ink_polygon() of the stroke with the recognizer's pen radius (what the
//                         daemon computes anyway; context for the next row, not part of it);
//   recognize + ink cert  recognize(StrokeInput) with that ink polygon: the path screening plus
//                         the ink-level certificate of the screened candidates (the daemon's
//                         pen-up path), beside the path-certified rows.
// Each time is measured twice: wall clock and the thread's CPU time (the machine is shared, so
// wall-clock tails include time the thread was not running). Target: p99 <= 5 ms per stroke.
//
// Accuracy (recognize_accuracy.hpp), printed first: shapes named right and non-shapes snapped on
// every labelled single-stroke drawing of ../shared/data/strokes (the $1 logs and the gestures of
// other people), all subjects beside leave-one-subject-out, the size x pen table beside the
// former rule, and the derivation of the default tolerance's fractions.
//
// The same cases on the generated strokes (tests/support/gen) beside the real ones, and the
// recognizer's figures (shapes named right, non-shapes left as ink) on both corpora: the
// generated corpus is never used to tune a threshold, its figures are printed to compare.
// Without the shared corpus only the generated rows are printed (the bench says so).
//
// Per class (recognize_classes.hpp), after the accuracy tables or alone with --classes (one
// recognition per drawing, quick): the shipped defaults on every labelled class, the diamonds and
// squares on a corner made from real rectangles, polygons of 5-8 corners made from real circles,
// one-stroke stars, and the classes simplified as sketch collections store drawings; --wrong lists
// every drawing named wrong. --rule-folds (recognize_rule_folds.hpp): each plausibility threshold
// (kDiamondSkew, kMaxBacktrack, kMinSharpCornerShare, kMinFittedCornerShare, ...,
// straight_fraction) chosen per held-out writer, the held-out figure beside the rule off and
// shipped. --invariance (recognize_invariance.hpp): every labelled single stroke moved, scaled,
// retimed, turned, mirrored, drawn backwards, and sent as other devices would (other sample
// rates, jitter, a coarse grid).
//
// Usage: recognize_bench [--json] [--repeat N] [--khz-stride K] [--accuracy-only |
//                         --timing-only | --derive-tolerance | --classes | --rule-folds |
//                         --invariance] [--wrong]
//        (data dir: $PENSHAPE_SHARED_DATA_DIR)
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "generated_accuracy.hpp"
#include "generated_corpus.hpp"
#include "penshape/core/ink.hpp"
#include "penshape/core/live_recognizer.hpp"
#include "penshape/core/recognize.hpp"
#include "recognize_accuracy.hpp"
#include "recognize_classes.hpp"
#include "recognize_invariance.hpp"
#include "recognize_rule_folds.hpp"
#include "stroke_corpora.hpp"

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

// One sample per millisecond between the first and last time stamps, linearly interpolated by
// time between the two logged samples around it; the last logged sample ends the stroke.
std::vector<StrokePoint> at_1khz(const std::vector<StrokePoint>& in) {
  if (in.size() < 2) return in;
  std::vector<StrokePoint> out;
  const double t0 = in.front().t, t1 = in.back().t;
  std::size_t j = 0;
  for (std::size_t k = 0;; ++k) {
    const double t = t0 + 1e-3 * static_cast<double>(k);
    if (t > t1) break;
    while (j + 2 < in.size() && in[j + 1].t < t) ++j;
    const StrokePoint& a = in[j];
    const StrokePoint& b = in[j + 1];
    const double f = b.t > a.t ? std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0) : 1.0;
    out.push_back({a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), t});
  }
  out.push_back(in.back());
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
  const auto i = static_cast<std::size_t>(std::lround(q * static_cast<double>(v.size() - 1)));
  return v[std::min(i, v.size() - 1)];
}

struct Density {
  std::string name;
  Series unthinned, offline, pen_up, pen_up_unthinned, per_sample, ink_build, ink_cert;
  std::size_t strokes = 0, samples = 0, snaps = 0, unthinned_snaps = 0, ink_snaps = 0;
  std::size_t differ = 0; // strokes whose class differs between thinned and unthinned
};

template <typename F>
void timed(Series& s, F&& f) {
  const double w = wall_seconds(), c = thread_cpu_seconds();
  f();
  s.wall_ms.push_back((wall_seconds() - w) * 1e3);
  s.cpu_ms.push_back((thread_cpu_seconds() - c) * 1e3);
}

Density run(const std::string& name, const std::vector<std::vector<StrokePoint>>& strokes,
            int repeat) {
  Density d;
  d.name = name;
  d.unthinned.name = "recognize, unthinned";
  d.offline.name = "recognize (offline)";
  d.pen_up.name = "live: pen-up";
  d.pen_up_unthinned.name = "live: pen-up unthin.";
  d.per_sample.name = "live: per sample";
  d.ink_build.name = "ink polygon";
  d.ink_cert.name = "recognize + ink cert";
  penshape::RecognizerConfig unthinned_config;
  unthinned_config.thin_tolerance_fraction = 0.0;
  penshape::LiveRecognizer live;
  penshape::LiveRecognizer live_unthinned(unthinned_config);
  for (int r = 0; r < repeat; ++r) {
    for (const auto& s : strokes) {
      ++d.strokes;
      d.samples += s.size();
      penshape::Recognition old_rec, rec;
      timed(d.unthinned, [&] { old_rec = penshape::recognize(s, unthinned_config); });
      timed(d.offline, [&] { rec = penshape::recognize(s); });
      if (rec.shape != penshape::ShapeClass::kFreeform) ++d.snaps;
      if (old_rec.shape != penshape::ShapeClass::kFreeform) ++d.unthinned_snaps;
      if (rec.shape != old_rec.shape) ++d.differ;

      for (const StrokePoint& p : s) timed(d.per_sample, [&] { live.add(p); });
      timed(d.pen_up, [&] { (void)live.finish(); });
      for (const StrokePoint& p : s) live_unthinned.add(p);
      timed(d.pen_up_unthinned, [&] { (void)live_unthinned.finish(); });

      // The ink polygon with the pen radius the recognizer uses, then the ink-certified run.
      const penshape::ToleranceChoice tol = penshape::choose_tolerance(s, {});
      std::vector<penshape::InkSample> ink_samples;
      ink_samples.reserve(s.size());
      for (const StrokePoint& p : s) ink_samples.push_back({p.x, p.y, tol.pen_radius});
      penshape::InkOptions options;
      options.radius_mm = tol.pen_radius;
      penshape::InkPolygon ink;
      timed(d.ink_build, [&] { ink = penshape::ink_polygon(ink_samples, options); });
      penshape::StrokeInput input;
      input.samples = s;
      input.ink = &ink;
      penshape::Recognition with_ink;
      timed(d.ink_cert, [&] { with_ink = penshape::recognize(input); });
      if (with_ink.shape != penshape::ShapeClass::kFreeform) ++d.ink_snaps;
    }
  }
  return d;
}

struct AccuracyRun {
  bool derive_only = false;  // the tolerance derivation only
  bool classes_only = false; // the per-class table only
  bool list_wrong = false;   // every miss of the per-class table
  bool rule_folds = false;   // the rule thresholds per held-out writer only
  bool invariance = false;   // the answers under transforms of the drawing and device only
};

// Every corpus together: the rule derived on all of their writers, figures per corpus.
void print_accuracy_figures(const std::filesystem::path& strokes, const AccuracyRun& run) {
  std::vector<penshape::bench::Drawing> all = penshape::bench::load_dollar1(strokes / "dollar1");
  const std::size_t dollar = all.size();
  const std::vector<penshape::bench::Drawing> gestures =
      penshape::bench::load_gestures(strokes / "gestures");
  all.insert(all.end(), gestures.begin(), gestures.end());
  std::printf("== accuracy: %zu $1 logs, %zu gesture drawings (single strokes) ==\n", dollar,
              gestures.size());
  if (run.rule_folds) {
    penshape::bench::print_rule_folds(all);
    return;
  }
  if (run.invariance) {
    penshape::bench::print_invariance(all);
    return;
  }
  if (!run.classes_only) penshape::bench::print_accuracy(all, {run.derive_only});
  if (!run.derive_only) penshape::bench::print_classes(all, {run.list_wrong});
  std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
  bool json = false;
  bool timing = true, accuracy = true;
  AccuracyRun accuracy_run;
  int repeat = 1;
  std::size_t khz_stride = 4;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--json") == 0) {
      json = true;
    } else if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--khz-stride") == 0 && i + 1 < argc) {
      khz_stride = static_cast<std::size_t>(std::max(1, std::atoi(argv[++i])));
    } else if (std::strcmp(argv[i], "--accuracy-only") == 0) {
      timing = false;
    } else if (std::strcmp(argv[i], "--timing-only") == 0) {
      accuracy = false;
    } else if (std::strcmp(argv[i], "--derive-tolerance") == 0) {
      timing = false, accuracy_run.derive_only = true;
    } else if (std::strcmp(argv[i], "--classes") == 0) {
      timing = false, accuracy_run.classes_only = true;
    } else if (std::strcmp(argv[i], "--rule-folds") == 0) {
      timing = false, accuracy_run.rule_folds = true;
    } else if (std::strcmp(argv[i], "--invariance") == 0) {
      timing = false, accuracy_run.invariance = true;
    } else if (std::strcmp(argv[i], "--wrong") == 0) {
      accuracy_run.list_wrong = true;
    } else {
      std::fprintf(stderr,
                   "usage: recognize_bench [--json] [--repeat N] [--khz-stride K] "
                   "[--accuracy-only | --timing-only | --derive-tolerance | --classes | "
                   "--rule-folds | --invariance] [--wrong]\n");
      return 2;
    }
  }
  const char* env = std::getenv("PENSHAPE_SHARED_DATA_DIR");
  const std::filesystem::path data = env ? env : PENSHAPE_SHARED_DATA_DIR;
  if (accuracy) print_accuracy_figures(data / "strokes", accuracy_run);
  if (!timing) return 0;
  const auto real = penshape::bench::real_dollar_strokes((data / "strokes" / "dollar1").string());
  const auto generated = penshape::bench::generated_strokes();
  std::fprintf(
      stderr, "recognize_bench: real strokes: %s; generated strokes: %zu (seed %llu)\n",
      real.empty()
          ? "none (no $1 logs in the shared corpus)"
          : ((data / "strokes" / "dollar1").string() + ", " + std::to_string(real.size())).c_str(),
      generated.size(), static_cast<unsigned long long>(penshape::gen::kCorpusSeed));
  const auto points_of = [](const std::vector<penshape::bench::LabelledStroke>& in) {
    std::vector<std::vector<StrokePoint>> out;
    out.reserve(in.size());
    for (const auto& s : in) out.push_back(s.points);
    return out;
  };
  const auto strokes = points_of(real);
  std::vector<std::vector<StrokePoint>> dense;
  for (std::size_t i = 0; i < strokes.size(); i += khz_stride) dense.push_back(at_1khz(strokes[i]));
  std::vector<Density> densities;
  if (!strokes.empty()) {
    densities.push_back(run("$1 as logged", strokes, repeat));
    densities.push_back(run("$1 at 1 kHz", dense, repeat));
  }
  densities.push_back(run("generated as drawn", points_of(generated), repeat));
  if (!json) {
    if (!real.empty()) penshape::bench::print_labelled_accuracy("real $1 logs", real);
    penshape::bench::print_labelled_accuracy("generated strokes", generated);
  }
  for (const Density& d : densities) {
    const Series* all[] = {&d.unthinned,  &d.offline,   &d.pen_up,  &d.pen_up_unthinned,
                           &d.per_sample, &d.ink_build, &d.ink_cert};
    if (!json) {
      std::printf(
          "%s: %zu strokes, %.0f samples per stroke; snaps: %zu thinned, %zu unthinned (%zu "
          "classes differ), %zu ink-certified; times in ms\n",
          d.name.c_str(), d.strokes,
          static_cast<double>(d.samples) / static_cast<double>(std::max<std::size_t>(1, d.strokes)),
          d.snaps, d.unthinned_snaps, d.differ, d.ink_snaps);
      std::printf("%-22s %8s %9s %9s %9s %9s %9s %9s\n", "case", "n", "p50 cpu", "p99 cpu",
                  "max cpu", "p50 wall", "p99 wall", "target");
    }
    for (const Series* s : all) {
      const double p50c = percentile(s->cpu_ms, 0.5), p99c = percentile(s->cpu_ms, 0.99);
      const double maxc = percentile(s->cpu_ms, 1.0);
      const double p50w = percentile(s->wall_ms, 0.5), p99w = percentile(s->wall_ms, 0.99);
      const bool per_stroke = s != &d.per_sample && s != &d.ink_build;
      if (json) {
        std::printf(
            "{\"density\":\"%s\",\"case\":\"%s\",\"n\":%zu,\"p50_cpu_ms\":%.4f,"
            "\"p99_cpu_ms\":%.4f,\"max_cpu_ms\":%.4f,\"p50_wall_ms\":%.4f,"
            "\"p99_wall_ms\":%.4f,\"target_p99_ms\":%s}\n",
            d.name.c_str(), s->name.c_str(), s->cpu_ms.size(), p50c, p99c, maxc, p50w, p99w,
            per_stroke ? "5" : "null");
      } else {
        std::printf("%-22s %8zu %9.3f %9.3f %9.3f %9.3f %9.3f %9s\n", s->name.c_str(),
                    s->cpu_ms.size(), p50c, p99c, maxc, p50w, p99w, per_stroke ? "p99<=5" : "-");
      }
    }
  }
  return 0;
}
