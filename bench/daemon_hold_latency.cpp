// Hold to snap → shape delivered, through the real daemon (the bench beside daemon_penup_latency):
// the bundled recording's eight real $1 strokes played at 1 kHz (one sample per ms, stamped with
// the monotonic clock as a tablet's reader thread would), each followed by a hold (700 ms within
// 2 device units), a 200 ms drag of 10 mm and pen-up; then the same strokes without a hold (the
// pen-up baseline, in the same run and daemon). A gRPC subscriber on a unix socket times each HOLD
// from the sample at which the hold was satisfied (HoldSnap.hold_time_us), each FOLLOW from the
// pen sample it follows (HoldSnap.pen_time_us), and the RELEASE and the pen-up baseline from
// pen-up. The subscriber is a thread of this process (daemon_penup_latency's former setup, which
// costs gRPC extra wake-ups): these figures are upper bounds. The first row is the machine's own
// 1 ms wake-up lateness, a floor no delivery beats.
//
//   build/release/bench/daemon_hold_latency [--rounds N] [--json]
#include <grpcpp/grpcpp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "bench_support.hpp"
#include "bench_tablet.hpp"
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

// Plays strokes at 1 kHz, stamping every sample with the time it is "read".
class HoldPlayer final : public penshape::bench::BenchTablet {
 public:
  using BenchTablet::BenchTablet;
  // Plays the stroke's tip-down samples, then (when `hold`) 700 ms of hold and a 200 ms drag of
  // 10 mm; returns the pen-up time (monotonic µs).
  std::int64_t play(std::uint64_t id, const penshape::Stroke& stroke, bool hold) {
    std::vector<penshape::PenSample> path;
    for (const auto& s : stroke.samples) {
      if (s.tip) path.push_back(s);
    }
    if (path.empty()) return monotonic_us();
    if (hold) {
      const penshape::PenSample rest = path.back();
      for (int i = 0; i < 700; ++i) {
        path.push_back(rest);
        path.back().x += (i % 3) - 1; // a tremor of a device unit
      }
      const double units = 10 * std::max(tablet_.x_resolution, 1.0);
      for (int i = 1; i <= 200; ++i) {
        path.push_back(rest);
        path.back().x = rest.x + static_cast<std::int32_t>(std::lround(units * i / 200));
      }
    }
    return play_samples(id, path);
  }
};

// Each shape event as the subscriber got it.
struct Arrival {
  std::int64_t at_us = 0;
  std::uint64_t stroke_id = 0;
  v1::ShapeTrigger trigger = v1::SHAPE_TRIGGER_UNSPECIFIED;
  std::int64_t hold_time_us = 0;
  std::int64_t pen_time_us = 0;
};

// Reads shape events until `finals` strokes got their final answer (pen-up or release).
std::vector<Arrival> subscribe(const std::string& address, std::size_t finals) {
  std::vector<Arrival> got;
  auto live = v1::Live::NewStub(grpc::CreateChannel(address, grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  auto stream = live->Subscribe(&ctx, v1::SubscribeRequest{});
  v1::LiveEvent event;
  std::size_t done = 0;
  while (done < finals && stream->Read(&event)) {
    if (!event.has_shape()) continue;
    const v1::ShapeRecognized& s = event.shape();
    got.push_back({monotonic_us(), s.stroke_id(), s.trigger(), s.hold().hold_time_us(),
                   s.hold().pen_time_us()});
    if (s.trigger() == v1::SHAPE_TRIGGER_PEN_UP || s.trigger() == v1::SHAPE_TRIGGER_RELEASE) ++done;
  }
  ctx.TryCancel();
  (void)stream->Finish();
  return got;
}

void print_row(bool json, const char* name, const std::vector<double>& ms, const char* target) {
  const penshape::bench::Percentiles p = penshape::bench::percentiles(ms);
  if (json) {
    std::printf(
        "{\"case\":\"%s\",\"n\":%zu,\"p50\":%.4f,\"p99\":%.4f,\"max\":%.4f,\"unit\":\"ms\"}\n",
        name, p.n, p.p50, p.p99, p.max);
  } else {
    std::printf("%-44s %6zu %9.3f %9.3f %9.3f ms  %s\n", name, p.n, p.p50, p.p99, p.max, target);
  }
}

} // namespace

int main(int argc, char** argv) {
  bool json = false;
  int rounds = 4;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--json") {
      json = true;
    } else if (a == "--rounds" && i + 1 < argc) {
      rounds = std::clamp(std::atoi(argv[++i]), 1, 100);
    } else {
      std::fprintf(stderr, "usage: daemon_hold_latency [--rounds N] [--json]\n");
      return 2;
    }
  }
  const auto decoded = penshape::drivers::replay(
      penshape::drivers::load_recording_file(std::string(PENSHAPE_SOURCE_DIR) +
                                             "/recordings/generated-shapes.hidrec"),
      penshape::drivers::ReplaySpeed::kAsFastAsPossible);
  const std::string dir = penshape::bench::make_scratch_dir();
  auto player = std::make_shared<HoldPlayer>(decoded.tablet);
  penshape::daemon::ServerOptions options;
  options.address = "unix:" + dir + "/hold.sock";
  options.config.limits.subscriber_queue_events = 1U << 16;
  options.config.settings.snap_trigger = penshape::daemon::SnapTrigger::kBoth;
  penshape::daemon::PenshapeServer server(
      options, {player, nullptr, penshape::daemon::make_recognizing_analyzer()});
  const std::size_t strokes = decoded.strokes.size() * static_cast<std::size_t>(rounds) * 2;
  std::vector<Arrival> got;
  std::thread reader([&] { got = subscribe(options.address, strokes); });
  while (server.hub().subscriber_count() < 1) std::this_thread::sleep_for(1ms);
  std::this_thread::sleep_for(100ms);
  std::map<std::uint64_t, std::int64_t> up_at;
  std::set<std::uint64_t> held; // strokes played with a hold
  std::uint64_t id = 0;
  for (int r = 0; r < rounds; ++r) {
    for (const bool hold : {true, false}) {
      for (const auto& s : decoded.strokes) {
        ++id;
        up_at[id] = player->play(id, s, hold);
        if (hold) held.insert(id);
        std::this_thread::sleep_for(30ms); // pen lifted between strokes
      }
    }
  }
  reader.join();
  std::vector<double> hold_ms, follow_ms, release_ms, penup_ms;
  for (const Arrival& a : got) {
    const double from_up = static_cast<double>(a.at_us - up_at[a.stroke_id]) / 1000.0;
    switch (a.trigger) {
      case v1::SHAPE_TRIGGER_HOLD:
        hold_ms.push_back(static_cast<double>(a.at_us - a.hold_time_us) / 1000.0);
        break;
      case v1::SHAPE_TRIGGER_FOLLOW:
        follow_ms.push_back(static_cast<double>(a.at_us - a.pen_time_us) / 1000.0);
        break;
      case v1::SHAPE_TRIGGER_RELEASE:
        release_ms.push_back(from_up);
        break;
      default: // a held stroke whose hold snapped nothing is not the baseline
        if (held.count(a.stroke_id) == 0) penup_ms.push_back(from_up);
        break;
    }
  }
  if (!json) {
    std::printf("-- %zu real strokes x %d rounds at 1 kHz, held then not (noisy shared machine)\n",
                decoded.strokes.size(), rounds);
    std::printf("%-44s %6s %9s %9s %9s\n", "case", "n", "p50", "p99", "max");
  }
  std::vector<double> lateness_ms;
  for (const double us : penshape::bench::wakeup_lateness_us(3000))
    lateness_ms.push_back(us / 1000);
  print_row(json, "baseline: this machine's 1 ms wake-up lateness", lateness_ms,
            "(no delivery beats it)");
  print_row(json, "baseline: pen-up -> shape (no hold)", penup_ms, "target p99 <= 8");
  print_row(json, "hold satisfied -> HOLD shape", hold_ms, "target p99 <= 8");
  print_row(json, "pen sample -> FOLLOW update", follow_ms, "target p99 <= 4");
  print_row(json, "pen-up -> RELEASE (final shape)", release_ms, "");
  std::filesystem::remove_all(dir);
  return 0;
}
