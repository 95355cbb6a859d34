// Pen-up → recognized shape delivered, through the real daemon: real pen strokes (the bundled
// recording of eight $1 strokes, decoded by the drivers) are fed at 1 kHz, one sample per
// millisecond as a 1 kHz tablet's reader thread would, into the pipeline with the recognizing
// analyzer (ink polygon + certified shape on the geometry workers); a real gRPC subscriber on a
// unix socket times each ShapeRecognized from the moment the pen lifted. Beside it, in the same
// run, the report → subscriber latency of the samples themselves (the live stream), and the
// baselines: the analyzer called directly, and a tablet's grouping session called directly (no
// daemon, no gRPC). The daemon groups each tablet's strokes (the default config). Two stroke sets:
// as recorded (the recording is at 200 Hz, so played one sample per ms they are drawn 5x faster),
// and resampled to 1 kHz (one sample per ms of the original time: what a 1 kHz tablet delivers, 5x
// the samples, drawn at the original pace). For each, two phases: a subscriber of samples and
// shapes, then one that also asks for live previews (computed on the idle lane while drawing). The
// process's CPU share while replaying and its peak RSS are printed for each (server and the
// subscriber share the process, so both are upper bounds for the daemon).
//
//   build/release/bench/daemon_penup_latency [--rounds N] [--json]
#include <grpcpp/grpcpp.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "bench_support.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"
#include "penshape/daemon/sample_source.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/daemon/shape_hub.hpp"
#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/replay.hpp"
#include "penshape/v1/live.grpc.pb.h"

namespace {

using namespace std::chrono_literals;
using penshape::daemon::monotonic_us;
namespace v1 = penshape::v1;

// Replays decoded strokes at 1 kHz, stamping every sample with the time it is "read".
class StrokeSource final : public penshape::daemon::SampleSource {
 public:
  explicit StrokeSource(penshape::TabletInfo tablet) : tablet_(std::move(tablet)) {}
  void start(penshape::daemon::SampleSink& sink) override {
    sink_ = &sink;
    penshape::daemon::DeviceDescriptor d;
    d.id = "bench";
    d.tablet = tablet_;
    sink.device_attached(d);
  }
  void stop() override {}
  [[nodiscard]] std::vector<penshape::daemon::DeviceDescriptor> devices() const override {
    return {};
  }
  // Plays one stroke; returns the pen-up time (monotonic µs) handed to the pipeline.
  std::int64_t play(std::uint64_t id, const penshape::Stroke& stroke) {
    penshape::Stroke out;
    out.id = id;
    out.tablet = tablet_;
    auto next = std::chrono::steady_clock::now();
    sink_->stroke_started("bench", id);
    for (penshape::PenSample s : stroke.samples) {
      std::this_thread::sleep_until(next);
      next += 1ms;
      s.time_us = monotonic_us();
      sink_->sample("bench", id, s);
      out.samples.push_back(s);
    }
    const std::int64_t up = monotonic_us();
    sink_->stroke_finished("bench", std::move(out));
    return up;
  }

 private:
  penshape::TabletInfo tablet_;
  penshape::daemon::SampleSink* sink_ = nullptr;
};

using penshape::bench::Percentiles;
using penshape::bench::percentiles;

void print_row(bool json, const char* name, const Percentiles& p, const char* unit,
               const char* target) {
  if (json) {
    std::printf(
        "{\"case\":\"%s\",\"n\":%zu,\"p50\":%.4f,\"p99\":%.4f,\"max\":%.4f,\"unit\":\"%s\"}\n",
        name, p.n, p.p50, p.p99, p.max, unit);
  } else {
    std::printf("%-48s %6zu %10.3f %10.3f %10.3f %-3s %s\n", name, p.n, p.p50, p.p99, p.max, unit,
                target);
  }
}

// The strokes a phase plays and the tablet they come from.
struct StrokeSet {
  std::string name;
  penshape::TabletInfo tablet;
  std::vector<penshape::Stroke> strokes;
};

// A stroke as a 1 kHz tablet reports it: one sample per millisecond of the original's time, by
// linear interpolation between the recorded samples (the recording is at 200 Hz), the last
// (tip-up) sample kept.
penshape::Stroke resampled_to_1khz(const penshape::Stroke& in) {
  penshape::Stroke out = in;
  out.samples.clear();
  const auto& s = in.samples;
  if (s.size() < 2) return in;
  std::size_t k = 0;
  for (std::int64_t t = s.front().time_us; t < s.back().time_us; t += 1000) {
    while (k + 2 < s.size() && s[k + 1].time_us <= t) ++k;
    const auto& a = s[k];
    const auto& b = s[k + 1];
    const double span = static_cast<double>(b.time_us - a.time_us);
    const double f = span > 0 ? static_cast<double>(t - a.time_us) / span : 0.0;
    penshape::PenSample p = a;
    p.time_us = t;
    p.x = static_cast<std::int32_t>(std::lround(a.x + f * (b.x - a.x)));
    p.y = static_cast<std::int32_t>(std::lround(a.y + f * (b.y - a.y)));
    p.pressure = static_cast<std::int32_t>(std::lround(a.pressure + f * (b.pressure - a.pressure)));
    p.tip = true;
    out.samples.push_back(p);
  }
  out.samples.push_back(s.back());
  return out;
}

// The stroke moved in time to start 1 ms after `*clock_us` (the previous stroke's pen-up), which
// then becomes its own last sample's time: strokes back to back, as the phases play them.
penshape::Stroke back_to_back(const penshape::Stroke& in, std::int64_t* clock_us) {
  penshape::Stroke out = in;
  if (out.samples.empty()) return out;
  const std::int64_t shift = *clock_us + 1000 - out.samples.front().time_us;
  for (auto& sample : out.samples) sample.time_us += shift;
  *clock_us = out.samples.back().time_us;
  return out;
}

struct PhaseResult {
  bool previews = false;
  std::vector<double> penup_ms;
  std::vector<double> sample_us;
  std::size_t previews_received = 0;
  double cpu_percent = 0.0; // process CPU time / wall time while replaying (server + subscriber)
  double rss_mb = 0.0;      // peak resident set of the whole process (VmHWM)
};

// Replays every stroke `rounds` times at 1 kHz through a fresh penshaped with one gRPC subscriber
// (samples, shapes, and previews when asked: previews then run on the idle lane while drawing).
PhaseResult run_phase(const std::string& dir, const StrokeSet& decoded,
                      const std::shared_ptr<penshape::daemon::StrokeAnalyzer>& analyzer, int rounds,
                      bool previews) {
  PhaseResult result;
  result.previews = previews;
  auto source = std::make_shared<StrokeSource>(decoded.tablet);
  penshape::daemon::ServerOptions options;
  options.address = "unix:" + dir + (previews ? "/previews.sock" : "/plain.sock");
  options.config.limits.subscriber_queue_events = 1U << 16;
  penshape::daemon::PenshapeServer server(options, {source, nullptr, analyzer});
  std::mutex m;
  std::map<std::uint64_t, std::int64_t> up_at;        // stroke id -> pen-up time
  std::map<std::uint64_t, std::int64_t> delivered_at; // stroke id -> shape received
  const std::size_t expected = decoded.strokes.size() * static_cast<std::size_t>(rounds);
  std::thread reader([&] {
    auto live =
        v1::Live::NewStub(grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
    grpc::ClientContext ctx;
    v1::SubscribeRequest request;
    request.set_include_samples(true);
    request.set_include_previews(previews);
    auto stream = live->Subscribe(&ctx, request);
    v1::LiveEvent event;
    std::size_t shapes = 0;
    while (shapes < expected && stream->Read(&event)) {
      const std::int64_t now = monotonic_us();
      if (event.has_samples()) {
        for (const auto& s : event.samples().samples()) {
          result.sample_us.push_back(static_cast<double>(now - s.time_us()));
        }
      }
      if (event.has_preview()) ++result.previews_received;
      if (event.has_shape()) {
        std::lock_guard lock(m);
        delivered_at[event.shape().stroke_id()] = now;
        ++shapes;
      }
    }
    ctx.TryCancel();
    (void)stream->Finish();
  });
  while (server.hub().subscriber_count() < 1) std::this_thread::sleep_for(1ms);
  std::this_thread::sleep_for(100ms);
  const double cpu0 = penshape::bench::process_usage().cpu_seconds;
  const auto wall0 = std::chrono::steady_clock::now();
  std::uint64_t id = 0;
  for (int r = 0; r < rounds; ++r) {
    for (const auto& s : decoded.strokes) {
      const std::int64_t up = source->play(++id, s);
      std::lock_guard lock(m);
      up_at[id] = up;
    }
  }
  reader.join();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const penshape::bench::ProcessUsage used = penshape::bench::process_usage();
  result.cpu_percent = 100.0 * (used.cpu_seconds - cpu0) / wall;
  result.rss_mb = static_cast<double>(used.peak_rss_kb) / 1024.0;
  for (const auto& [sid, t] : delivered_at) {
    if (up_at.count(sid) != 0) {
      result.penup_ms.push_back(static_cast<double>(t - up_at[sid]) / 1000.0);
    }
  }
  return result;
}

} // namespace

int main(int argc, char** argv) {
  bool json = false;
  int rounds = 5;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--json") {
      json = true;
    } else if (a == "--rounds" && i + 1 < argc) {
      rounds = std::max(1, std::atoi(argv[++i]));
    } else {
      std::fprintf(stderr, "usage: daemon_penup_latency [--rounds N] [--json]\n");
      return 2;
    }
  }
  const std::string file =
      std::string(PENSHAPE_SOURCE_DIR) + "/recordings/dollar1-shapes.xppen-deco01v2.hidrec";
  const auto recording = penshape::drivers::load_recording_file(file);
  const auto decoded =
      penshape::drivers::replay(recording, penshape::drivers::ReplaySpeed::kAsFastAsPossible);

  StrokeSet recorded{"as recorded (200 Hz)", decoded.tablet, decoded.strokes};
  StrokeSet dense{"resampled to 1 kHz", decoded.tablet, {}};
  for (const auto& stroke : decoded.strokes) dense.strokes.push_back(resampled_to_1khz(stroke));

  auto analyzer = penshape::daemon::make_recognizing_analyzer();
  const std::string dir = penshape::bench::make_scratch_dir();
  if (!json) std::printf("%-48s %6s %10s %10s %10s\n", "case", "n", "p50", "p99", "max");
  for (const StrokeSet* set : {&recorded, &dense}) {
    // Baseline: the analyzer alone, on the same strokes.
    std::vector<double> direct_ms;
    for (int r = 0; r < rounds; ++r) {
      for (const auto& s : set->strokes) {
        const auto t0 = std::chrono::steady_clock::now();
        (void)analyzer->analyze(s, penshape::daemon::PenSettings{}, {});
        direct_ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count());
      }
    }
    // Baseline with grouping: the same strokes added in order to one tablet's grouping session
    // (ink polygon, the stroke alone, then unions with its recent strokes), back to back in time
    // as the phases play them: what the daemon's strand computes after each pen-up.
    std::vector<double> grouped_ms;
    auto session =
        analyzer->group_session(penshape::daemon::PenSettings{}, penshape::GroupingConfig{});
    std::int64_t clock_us = 0;
    for (int r = 0; r < rounds; ++r) {
      for (const auto& s : set->strokes) {
        const penshape::Stroke timed = back_to_back(s, &clock_us);
        const auto t0 = std::chrono::steady_clock::now();
        (void)session->add(timed, true, {});
        grouped_ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count());
      }
    }
    std::size_t max_samples = 0;
    for (const auto& s : set->strokes) max_samples = std::max(max_samples, s.samples.size());
    if (!json) {
      std::printf("-- %zu real strokes %s, up to %zu samples, x %d rounds, played at 1 kHz\n",
                  set->strokes.size(), set->name.c_str(), max_samples, rounds);
    }
    const std::string tag = set == &dense ? " [1 kHz]" : "";
    print_row(json, ("baseline: analyzer called directly" + tag).c_str(), percentiles(direct_ms),
              "ms", "");
    print_row(json, ("baseline: grouping session called directly" + tag).c_str(),
              percentiles(grouped_ms), "ms", "");
    for (bool previews : {false, true}) {
      const PhaseResult phase = run_phase(dir, *set, analyzer, rounds, previews);
      const std::string t = tag + (previews ? " (+previews)" : "");
      print_row(json, ("pen-up -> shape at gRPC subscriber" + t).c_str(),
                percentiles(phase.penup_ms), "ms", "(target p99 <= 16 ms)");
      print_row(json, ("report -> sample at gRPC subscriber" + t).c_str(),
                percentiles(phase.sample_us), "us", "(target p99 < 1000 us)");
      if (json) {
        std::printf(
            "{\"case\":\"process%s\",\"cpu_percent\":%.1f,\"rss_mb\":%.1f,"
            "\"previews\":%zu}\n",
            t.c_str(), phase.cpu_percent, phase.rss_mb, phase.previews_received);
      } else {
        std::printf(
            "%-48s cpu %5.1f%% of one core, peak RSS %.1f MB (target < 50 MB), %zu "
            "previews\n",
            ("process" + t).c_str(), phase.cpu_percent, phase.rss_mb, phase.previews_received);
      }
    }
  }
  std::filesystem::remove_all(dir);
  return 0;
}
