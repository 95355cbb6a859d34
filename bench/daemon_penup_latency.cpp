// Pen-up → recognized shape delivered, through the real daemon: real pen strokes (the bundled
// recording of eight $1 strokes, decoded by the drivers) are fed at 1 kHz, one sample per
// millisecond as a 1 kHz tablet's reader thread would, into the pipeline with the recognizing
// analyzer (ink polygon + certified shape on the geometry workers); a real gRPC subscriber on a
// unix socket times each ShapeRecognized from the moment the pen lifted. The subscriber is a
// process of its own, as an app is (this program run again with --subscribe): in one process,
// gRPC's client and server would share one poller set and threads, and each sample would take
// wake-ups a real app does not pay; one row keeps that former in-process setup for comparison.
// Beside it, in the same run, the report → subscriber latency of the samples themselves (the live
// stream; the monotonic clock is the same in both processes), and the baselines: the analyzer
// called directly, a tablet's grouping session called directly (no daemon, no gRPC), and the
// machine's own wake-up jitter (a thread sleeping to each millisecond, nothing else running): a
// floor no delivery beats, since a sample crosses several thread wake-ups. The daemon groups each
// tablet's strokes (the default config). Two stroke sets: as recorded (the recording is at 200 Hz,
// so played one sample per ms they are drawn 5x faster), and resampled to 1 kHz (one sample per ms
// of the original time: what a 1 kHz tablet delivers, 5x the samples, drawn at the original pace).
// For each, two phases: a subscriber of samples and shapes, then one that also asks for live
// previews (computed on the idle lane while drawing). The daemon process's CPU share while
// replaying and its peak RSS are printed for each (the bench's player thread included, so both are
// upper bounds for the daemon), and pen-up -> shape is split with the daemon's own timings: the
// stroke's wait for its strand, and the analysis with grouping.
//
// Each stroke set is played 13 times by default (--rounds): 104 strokes per row, so that p99 is
// the second worst stroke rather than the worst one (the max is printed too).
//
//   build/release/bench/daemon_penup_latency [--rounds N] [--json] [--stages-only]
//                                             [--set recorded|1khz] [--previews-only]
// --set and --previews-only run a part of the rows (a quick look while iterating; the default
// runs every row).
#include <fcntl.h>
#include <grpcpp/grpcpp.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "bench_support.hpp"
#include "bench_tablet.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"
#include "penshape/daemon/sample_source.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/daemon/shape_hub.hpp"
#include "penshape/daemon/worker_pool.hpp"
#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/replay.hpp"
#include "penshape/v1/live.grpc.pb.h"
#include "penup_stages.hpp"

namespace {

using namespace std::chrono_literals;
using penshape::daemon::monotonic_us;
namespace v1 = penshape::v1;

// Replays decoded strokes at 1 kHz, stamping every sample with the time it is "read".
class StrokeSource final : public penshape::bench::BenchTablet {
 public:
  using BenchTablet::BenchTablet;
  // Plays one stroke; returns the pen-up time (monotonic µs) handed to the pipeline.
  std::int64_t play(std::uint64_t id, const penshape::Stroke& stroke) {
    return play_samples(id, stroke.samples);
  }
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
    // In double: the unsigned difference would wrap where the pressure falls.
    p.pressure = static_cast<std::uint32_t>(
        std::lround(a.pressure + f * (static_cast<double>(b.pressure) - a.pressure)));
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

// What a subscriber received: each sample's report -> delivery latency, each shape's arrival.
struct Received {
  std::vector<double> sample_us;
  std::map<std::uint64_t, std::int64_t> shape_at; // stroke id -> monotonic µs at arrival
  std::vector<double> queued_ms, compute_ms;      // the daemon's own timings of each shape
  std::size_t previews = 0;
};

// Subscribes to samples, shapes (and previews when asked) until `expected` shapes arrived.
Received subscribe_until(const std::string& address, bool previews, std::size_t expected) {
  Received got;
  auto live = v1::Live::NewStub(grpc::CreateChannel(address, grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  v1::SubscribeRequest request;
  request.set_include_samples(true);
  request.set_include_previews(previews);
  auto stream = live->Subscribe(&ctx, request);
  v1::LiveEvent event;
  while (got.shape_at.size() < expected && stream->Read(&event)) {
    const std::int64_t now = monotonic_us();
    for (const auto& s : event.samples().samples()) {
      got.sample_us.push_back(static_cast<double>(now - s.time_us()));
    }
    if (event.has_preview()) ++got.previews;
    if (event.has_shape()) {
      got.shape_at[event.shape().stroke_id()] = now;
      got.queued_ms.push_back(static_cast<double>(event.shape().timings().queued_us()) / 1000.0);
      got.compute_ms.push_back(static_cast<double>(event.shape().timings().compute_us()) / 1000.0);
    }
  }
  ctx.TryCancel();
  (void)stream->Finish();
  return got;
}

// The subscriber process (--subscribe ADDRESS PREVIEWS EXPECTED): what it received goes to stdout
// once it is done ("s µs" per sample, "p stroke µs" per shape, "t queued_ms compute_ms" per
// shape, "v count"), so no write competes with the deliveries it times.
int run_subscriber(const std::string& address, bool previews, std::size_t expected) {
  const Received got = subscribe_until(address, previews, expected);
  std::string out;
  for (const double us : got.sample_us) out += "s " + std::to_string(std::llround(us)) + "\n";
  for (const auto& [id, at] : got.shape_at) {
    out += "p " + std::to_string(id) + " " + std::to_string(at) + "\n";
  }
  for (std::size_t i = 0; i < got.queued_ms.size(); ++i) {
    out += "t " + std::to_string(got.queued_ms[i]) + " " + std::to_string(got.compute_ms[i]) + "\n";
  }
  out += "v " + std::to_string(got.previews) + "\n";
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

Received parse_received(std::istream& in) {
  Received got;
  std::string kind;
  while (in >> kind) {
    if (kind == "s") {
      double us = 0;
      in >> us;
      got.sample_us.push_back(us);
    } else if (kind == "p") {
      std::uint64_t id = 0;
      std::int64_t at = 0;
      in >> id >> at;
      got.shape_at[id] = at;
    } else if (kind == "t") {
      double queued = 0;
      double compute = 0;
      in >> queued >> compute;
      got.queued_ms.push_back(queued);
      got.compute_ms.push_back(compute);
    } else if (kind == "v") {
      in >> got.previews;
    }
  }
  return got;
}

// This program run again as a subscriber process; its report is read once it exits (at most
// `timeout` after the last stroke was played, then it is killed).
class SubscriberProcess {
 public:
  SubscriberProcess(const std::string& address, bool previews, std::size_t expected) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    std::vector<std::string> args = {"daemon_penup_latency", "--subscribe", address,
                                     previews ? "1" : "0", std::to_string(expected)};
    std::vector<char*> argv;
    argv.reserve(args.size() + 1);
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int failed =
        posix_spawn(&pid_, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    if (failed != 0) {
      ::close(fds[0]);
      throw std::runtime_error("cannot start the subscriber process");
    }
    // Drained while the phase runs, so the child never blocks on a full pipe.
    reader_ = std::thread([this, fd = fds[0]] {
      char buffer[1 << 16];
      for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n <= 0) break;
        report_.append(buffer, static_cast<std::size_t>(n));
      }
      ::close(fd);
    });
  }
  ~SubscriberProcess() {
    if (reader_.joinable()) (void)finish(std::chrono::seconds(0));
  }
  SubscriberProcess(const SubscriberProcess&) = delete;
  SubscriberProcess& operator=(const SubscriberProcess&) = delete;

  Received finish(std::chrono::seconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    int status = 0;
    while (::waitpid(pid_, &status, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > deadline) {
        ::kill(pid_, SIGKILL);
        (void)::waitpid(pid_, &status, 0);
        break;
      }
      std::this_thread::sleep_for(10ms);
    }
    reader_.join();
    std::istringstream in(report_);
    return parse_received(in);
  }

 private:
  pid_t pid_ = 0;
  std::thread reader_;
  std::string report_;
};

struct PhaseResult {
  std::vector<double> penup_ms;
  std::vector<double> queued_ms, compute_ms; // the daemon's timings: waiting, then analysing
  std::vector<double> sample_us;
  std::size_t previews_received = 0;
  double cpu_percent = 0.0; // this process's CPU time / wall time while replaying (the daemon's)
  double rss_mb = 0.0;      // peak resident set of this process (VmHWM)
};

struct PhaseOptions {
  bool previews = false;
  bool subscriber_in_process =
      false; // the former setup: the subscriber shares the daemon's process
};

// Replays every stroke `rounds` times at 1 kHz through a fresh penshaped with one gRPC subscriber
// (samples, shapes, and previews when asked: previews then run on the idle lane while drawing).
PhaseResult run_phase(const std::string& dir, const StrokeSet& decoded,
                      const std::shared_ptr<penshape::daemon::StrokeAnalyzer>& analyzer, int rounds,
                      PhaseOptions phase) {
  auto source = std::make_shared<StrokeSource>(decoded.tablet);
  penshape::daemon::ServerOptions options;
  options.address = "unix:" + dir + "/phase.sock";
  options.config.limits.subscriber_queue_events = 1U << 16;
  penshape::daemon::PenshapeServer server(options, {source, nullptr, analyzer});
  const std::size_t expected = decoded.strokes.size() * static_cast<std::size_t>(rounds);
  std::optional<SubscriberProcess> child;
  Received in_process;
  std::thread reader;
  if (phase.subscriber_in_process) {
    reader = std::thread(
        [&] { in_process = subscribe_until(options.address, phase.previews, expected); });
  } else {
    child.emplace(options.address, phase.previews, expected);
  }
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (server.hub().subscriber_count() < 1) {
    if (std::chrono::steady_clock::now() > give_up) {
      std::fprintf(stderr, "daemon_penup_latency: the subscriber did not subscribe within 20 s\n");
      std::_Exit(1); // a reader thread may still wait on its stream
    }
    std::this_thread::sleep_for(1ms);
  }
  std::this_thread::sleep_for(100ms);
  const double cpu0 = penshape::bench::process_usage().cpu_seconds;
  const auto wall0 = std::chrono::steady_clock::now();
  std::map<std::uint64_t, std::int64_t> up_at; // stroke id -> pen-up time
  std::uint64_t id = 0;
  for (int r = 0; r < rounds; ++r) {
    for (const auto& s : decoded.strokes) {
      ++id;
      up_at[id] = source->play(id, s);
    }
  }
  Received got;
  if (reader.joinable()) {
    reader.join();
    got = std::move(in_process);
  } else {
    got = child->finish(std::chrono::seconds(60));
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const penshape::bench::ProcessUsage used = penshape::bench::process_usage();
  PhaseResult result;
  result.cpu_percent = 100.0 * (used.cpu_seconds - cpu0) / wall;
  result.rss_mb = static_cast<double>(used.peak_rss_kb) / 1024.0;
  result.sample_us = std::move(got.sample_us);
  result.previews_received = got.previews;
  result.queued_ms = std::move(got.queued_ms);
  result.compute_ms = std::move(got.compute_ms);
  for (const auto& [sid, t] : got.shape_at) {
    if (up_at.count(sid) != 0) {
      result.penup_ms.push_back(static_cast<double>(t - up_at[sid]) / 1000.0);
    }
  }
  return result;
}

// A tablet's grouping session called directly (no daemon, no gRPC): the strokes added in order,
// back to back in time as the phases play them; the time of each add(), in ms.
std::vector<double> grouping_session_ms(penshape::daemon::StrokeAnalyzer& analyzer,
                                        const StrokeSet& set, int rounds,
                                        const penshape::daemon::InkOffload& offload) {
  std::vector<double> out;
  auto session =
      analyzer.group_session(penshape::daemon::PenSettings{}, penshape::GroupingConfig{});
  std::int64_t clock_us = 0;
  for (int r = 0; r < rounds; ++r) {
    for (const auto& s : set.strokes) {
      const penshape::Stroke timed = back_to_back(s, &clock_us);
      const auto t0 = std::chrono::steady_clock::now();
      (void)session->add(timed, true, {}, offload);
      out.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  return out;
}

// Each step of the pen-up analysis in thread CPU time (penup_stages.hpp), on the set's strokes
// back to back in time, `rounds` times.
void print_stages(bool json, const StrokeSet& set, int rounds,
                  penshape::daemon::StrokeAnalyzer& analyzer) {
  std::vector<penshape::Stroke> timed;
  std::int64_t clock_us = 0;
  for (int r = 0; r < rounds; ++r) {
    for (const auto& s : set.strokes) timed.push_back(back_to_back(s, &clock_us));
  }
  penshape::bench::print_penup_stages(json, set.name == "resampled to 1 kHz" ? " [1 kHz]" : "",
                                      timed, analyzer);
}

void print_phase(bool json, const std::string& t, const PhaseResult& phase) {
  print_row(json, ("pen-up -> shape at gRPC subscriber" + t).c_str(), percentiles(phase.penup_ms),
            "ms", "(target p99 <= 8 ms)");
  print_row(json, ("  of it: stroke waiting for its strand" + t).c_str(),
            percentiles(phase.queued_ms), "ms", "");
  print_row(json, ("  of it: strand analysing and grouping" + t).c_str(),
            percentiles(phase.compute_ms), "ms", "");
  print_row(json, ("report -> sample at gRPC subscriber" + t).c_str(), percentiles(phase.sample_us),
            "us", "(target p99 < 1000 us)");
  if (json) {
    std::printf(
        "{\"case\":\"process%s\",\"cpu_percent\":%.1f,\"rss_mb\":%.1f,"
        "\"previews\":%zu}\n",
        t.c_str(), phase.cpu_percent, phase.rss_mb, phase.previews_received);
  } else {
    std::printf(
        "%-48s cpu %5.1f%% of one core, peak RSS %.1f MB (target < 50 MB), %zu "
        "previews\n",
        ("daemon process" + t).c_str(), phase.cpu_percent, phase.rss_mb, phase.previews_received);
  }
}

} // namespace

int main(int argc, char** argv) {
  if (argc == 5 && std::string(argv[1]) == "--subscribe") {
    return run_subscriber(argv[2], std::string(argv[3]) == "1",
                          static_cast<std::size_t>(std::atol(argv[4])));
  }
  bool json = false;
  bool stages_only = false;
  bool previews_only = false;
  std::string only_set; // empty: both stroke sets
  int rounds = 13;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--json") {
      json = true;
    } else if (a == "--stages-only") {
      stages_only = true;
    } else if (a == "--previews-only") {
      previews_only = true;
    } else if (a == "--rounds" && i + 1 < argc) {
      rounds = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--set" && i + 1 < argc &&
               (std::string(argv[i + 1]) == "recorded" || std::string(argv[i + 1]) == "1khz")) {
      only_set = argv[++i];
    } else {
      std::fprintf(stderr,
                   "usage: daemon_penup_latency [--rounds N] [--json] [--stages-only] "
                   "[--set recorded|1khz] [--previews-only]\n");
      return 2;
    }
  }
  const std::string file = std::string(PENSHAPE_SOURCE_DIR) + "/recordings/generated-shapes.hidrec";
  const auto recording = penshape::drivers::load_recording_file(file);
  const auto decoded =
      penshape::drivers::replay(recording, penshape::drivers::ReplaySpeed::kAsFastAsPossible);

  StrokeSet recorded{"as recorded (200 Hz)", decoded.tablet, decoded.strokes};
  StrokeSet dense{"resampled to 1 kHz", decoded.tablet, {}};
  for (const auto& stroke : decoded.strokes) dense.strokes.push_back(resampled_to_1khz(stroke));

  std::vector<const StrokeSet*> sets;
  if (only_set != "1khz") sets.push_back(&recorded);
  if (only_set != "recorded") sets.push_back(&dense);
  auto analyzer = penshape::daemon::make_recognizing_analyzer();
  const std::string dir = penshape::bench::make_scratch_dir();
  if (!json) std::printf("%-48s %6s %10s %10s %10s\n", "case", "n", "p50", "p99", "max");
  if (stages_only) {
    for (const StrokeSet* set : sets) print_stages(json, *set, rounds, *analyzer);
    return 0;
  }
  print_row(json, "baseline: this machine's 1 ms wake-up lateness",
            percentiles(penshape::bench::wakeup_lateness_us(5000)), "us", "(no delivery beats it)");
  for (const StrokeSet* set : sets) {
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
    // Baseline with grouping: the same strokes added in order to one tablet's grouping session,
    // all on one thread as before (ink polygon, then the stroke alone, then unions with its recent
    // strokes), and as the daemon's strand now does it (the ink polygon built on a second worker
    // while the path is fitted).
    const std::vector<double> serial_ms = grouping_session_ms(*analyzer, *set, rounds, {});
    penshape::daemon::WorkerPool helper(1, 16, penshape::daemon::WorkerPriority::kNormal);
    penshape::daemon::InkOffload offload;
    offload.run_elsewhere = [&helper](std::function<void()> job) {
      return helper.submit([job = std::move(job)](const auto& /*stop*/) { job(); });
    };
    const std::vector<double> grouped_ms = grouping_session_ms(*analyzer, *set, rounds, offload);
    std::size_t max_samples = 0;
    for (const auto& s : set->strokes) max_samples = std::max(max_samples, s.samples.size());
    if (!json) {
      std::printf("-- %zu real strokes %s, up to %zu samples, x %d rounds, played at 1 kHz\n",
                  set->strokes.size(), set->name.c_str(), max_samples, rounds);
    }
    const std::string tag = set == &dense ? " [1 kHz]" : "";
    print_stages(json, *set, rounds, *analyzer);
    print_row(json, ("baseline: analyzer called directly" + tag).c_str(), percentiles(direct_ms),
              "ms", "");
    print_row(json, ("baseline: grouping session, one thread" + tag).c_str(),
              percentiles(serial_ms), "ms", "");
    print_row(json, ("baseline: grouping session, ink on a 2nd worker" + tag).c_str(),
              percentiles(grouped_ms), "ms", "");
    for (bool previews : {false, true}) {
      if (previews_only && !previews) continue;
      const PhaseResult phase = run_phase(dir, *set, analyzer, rounds, {.previews = previews});
      print_phase(json, tag + (previews ? " (+previews)" : ""), phase);
    }
    if (set == &recorded && !previews_only) {
      const PhaseResult former =
          run_phase(dir, *set, analyzer, rounds, {.subscriber_in_process = true});
      print_phase(json, " (subscriber in the daemon's process)", former);
    }
  }
  std::filesystem::remove_all(dir);
  return 0;
}
