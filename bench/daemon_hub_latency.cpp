// Live fan-out latency through the real daemon: a source emits pen samples at 1 kHz (as a tablet's
// reader thread would), the daemon's pipeline publishes them to the shape hub, and subscribers
// receive them — in process straight from the hub (the baseline: no gRPC) and as real gRPC
// clients over a unix socket. Latency = sample emitted (CLOCK_MONOTONIC) → subscriber holds it.
// The source hands raw reports to the daemon the way the device manager source does (only while
// someone captures them); the last case measures a sample subscriber beside one raw capture.
// Also the process's CPU use (utime + stime from /proc/self/stat) and resident memory
// (/proc/self/status), idle and under load. The clients run in this process too, so CPU and RSS
// include them: an upper bound for the daemon alone.
//
//   build/release/bench/daemon_hub_latency [--seconds N] [--json]
#include <grpcpp/grpcpp.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_support.hpp"
#include "penshape/daemon/sample_source.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/daemon/shape_hub.hpp"
#include "penshape/v1/live.grpc.pb.h"

namespace {

using namespace std::chrono_literals;
using penshape::daemon::monotonic_us;
namespace v1 = penshape::v1;

// A pen on a 1 kHz tablet: one sample per millisecond, stamped with the time it was read.
class PacedSource final : public penshape::daemon::SampleSource {
 public:
  void start(penshape::daemon::SampleSink& sink) override {
    sink_ = &sink;
    penshape::daemon::DeviceDescriptor d;
    d.id = "bench";
    d.tablet.x_max = 20000;
    d.tablet.y_max = 15000;
    sink.device_attached(d);
  }
  void stop() override {}
  [[nodiscard]] std::vector<penshape::daemon::DeviceDescriptor> devices() const override {
    return {};
  }
  // Emits `count` samples at `rate_hz`, blocking.
  void emit(int count, int rate_hz) {
    const auto period = std::chrono::microseconds(1'000'000 / rate_hz);
    std::array<std::uint8_t, 8> report{0x02, 0, 0x10, 0x27, 0x64, 0x00, 0x00, 0x01};
    auto next = std::chrono::steady_clock::now();
    for (int i = 0; i < count; ++i) {
      std::this_thread::sleep_until(next);
      next += period;
      penshape::PenSample s;
      s.x = i % 20000;
      s.y = 100;
      s.tip = true;
      s.in_range = true;
      s.time_us = monotonic_us();
      // The device manager source's read path: the report itself first, only while someone
      // captures raw reports.
      if (sink_->wants_raw_reports()) {
        report[1] = static_cast<std::uint8_t>(i);
        sink_->raw_report("bench", report, s.time_us);
      }
      sink_->sample("bench", 1, s);
    }
  }

 private:
  penshape::daemon::SampleSink* sink_ = nullptr;
};

struct Row {
  std::string name;
  std::string path;
  int subscribers = 0;
  penshape::bench::Percentiles latency_us;
  std::uint64_t lost = 0;
  double cpu_percent = 0;
  long rss_kb = 0;
};

// Runs one case: `grpc_subscribers` gRPC clients (or one in-process hub subscription when 0),
// beside `raw_captures` gRPC clients taking raw reports (as `penshape record` does) whose own
// latency is not measured.
Row run_case(const std::string& name, int grpc_subscribers, int samples, const std::string& dir,
             int raw_captures = 0) {
  auto source = std::make_shared<PacedSource>();
  penshape::daemon::ServerOptions options;
  options.address = "unix:" + dir + "/bench.sock";
  penshape::daemon::PenshapeServer server(options, {source, nullptr, nullptr});

  Row row;
  row.name = name;
  row.subscribers = std::max(grpc_subscribers, 1);
  row.path = grpc_subscribers == 0 ? "hub (in process)" : "gRPC unix socket";
  std::vector<std::vector<std::int64_t>> latencies(static_cast<std::size_t>(row.subscribers));
  std::atomic<std::uint64_t> lost{0};
  std::vector<std::thread> readers;
  std::unique_ptr<penshape::daemon::Subscription> direct;

  if (grpc_subscribers == 0) {
    penshape::daemon::EventFilter filter;
    filter.samples = true;
    direct = server.hub().subscribe(filter, 4096);
    readers.emplace_back([&] {
      int got = 0;
      while (got < samples) {
        auto d = direct->next(1s);
        if (!d.event) break;
        lost += d.dropped;
        latencies[0].push_back(monotonic_us() - d.event->samples().samples(0).time_us());
        ++got;
      }
    });
  } else {
    for (int c = 0; c < grpc_subscribers; ++c) {
      readers.emplace_back([&, c] {
        auto live = v1::Live::NewStub(
            grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
        grpc::ClientContext ctx;
        v1::SubscribeRequest request;
        request.set_include_samples(true);
        auto reader = live->Subscribe(&ctx, request);
        v1::LiveEvent event;
        int got = 0;
        while (got < samples && reader->Read(&event)) {
          if (event.has_dropped()) {
            lost += event.dropped().count();
            continue;
          }
          if (!event.has_samples()) continue;
          latencies[static_cast<std::size_t>(c)].push_back(monotonic_us() -
                                                           event.samples().samples(0).time_us());
          ++got;
        }
        ctx.TryCancel();
        (void)reader->Finish();
      });
    }
  }
  std::vector<std::unique_ptr<grpc::ClientContext>> capture_contexts;
  std::vector<std::thread> captures;
  for (int c = 0; c < raw_captures; ++c) {
    capture_contexts.push_back(std::make_unique<grpc::ClientContext>());
    captures.emplace_back([&address = options.address, ctx = capture_contexts.back().get()] {
      auto live =
          v1::Live::NewStub(grpc::CreateChannel(address, grpc::InsecureChannelCredentials()));
      v1::SubscribeRequest request;
      request.set_include_raw_reports(true);
      auto reader = live->Subscribe(ctx, request);
      v1::LiveEvent event;
      while (reader->Read(&event)) {
      }
      (void)reader->Finish();
    });
  }
  while (server.hub().subscriber_count() <
         static_cast<std::size_t>(row.subscribers) + static_cast<std::size_t>(raw_captures)) {
    std::this_thread::sleep_for(1ms);
  }
  std::this_thread::sleep_for(100ms); // connections settle
  const penshape::bench::ProcessUsage before = penshape::bench::process_usage();
  const auto t0 = std::chrono::steady_clock::now();
  source->emit(samples, 1000);
  for (auto& t : readers) t.join();
  for (auto& ctx : capture_contexts) ctx->TryCancel();
  for (auto& t : captures) t.join();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const penshape::bench::ProcessUsage after = penshape::bench::process_usage();
  direct.reset();
  std::vector<double> all;
  for (auto& l : latencies) {
    for (std::int64_t us : l) all.push_back(static_cast<double>(us));
  }
  row.latency_us = penshape::bench::percentiles(std::move(all));
  row.lost = lost;
  row.cpu_percent = 100.0 * (after.cpu_seconds - before.cpu_seconds) / wall;
  row.rss_kb = after.rss_kb;
  return row;
}

// No events; `subscribers` gRPC clients subscribed and waiting (as idle drawing apps would be).
Row idle_case(const std::string& dir, double seconds, int subscribers) {
  penshape::daemon::ServerOptions options;
  options.address = "unix:" + dir + "/idle.sock";
  penshape::daemon::PenshapeServer server(options);
  std::vector<std::unique_ptr<grpc::ClientContext>> contexts;
  std::vector<std::thread> clients;
  for (int c = 0; c < subscribers; ++c) {
    contexts.push_back(std::make_unique<grpc::ClientContext>());
    clients.emplace_back([&address = options.address, ctx = contexts.back().get()] {
      auto live =
          v1::Live::NewStub(grpc::CreateChannel(address, grpc::InsecureChannelCredentials()));
      auto reader = live->Subscribe(ctx, {});
      v1::LiveEvent event;
      while (reader->Read(&event)) {
      }
      (void)reader->Finish();
    });
  }
  while (server.hub().subscriber_count() < static_cast<std::size_t>(subscribers)) {
    std::this_thread::sleep_for(1ms);
  }
  std::this_thread::sleep_for(200ms);
  const penshape::bench::ProcessUsage before = penshape::bench::process_usage();
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  const penshape::bench::ProcessUsage after = penshape::bench::process_usage();
  for (auto& ctx : contexts) ctx->TryCancel();
  for (auto& t : clients) t.join();
  Row row;
  row.name = subscribers == 0 ? "idle" : "idle, subscribed";
  row.subscribers = subscribers;
  row.path = subscribers == 0 ? "no clients" : "gRPC unix socket";
  row.cpu_percent = 100.0 * (after.cpu_seconds - before.cpu_seconds) / seconds;
  row.rss_kb = after.rss_kb;
  return row;
}

} // namespace

int main(int argc, char** argv) {
  const auto args = penshape::bench::parse_seconds_args(argc, argv, "daemon_hub_latency", 3);
  if (!args) return 2;
  const double seconds = args->seconds;
  const bool json = args->json;
  const std::string dir = penshape::bench::make_scratch_dir();
  const int samples = static_cast<int>(seconds * 1000);

  std::vector<Row> rows;
  rows.push_back(idle_case(dir, std::min(seconds, 2.0), 0));
  rows.push_back(idle_case(dir, std::min(seconds, 2.0), 8));
  rows.push_back(run_case("baseline: hub direct", 0, samples, dir));
  rows.push_back(run_case("gRPC, 1 subscriber", 1, samples, dir));
  rows.push_back(run_case("gRPC, 8 subscribers", 8, samples, dir));
  rows.push_back(run_case("gRPC, 1 + raw capture", 1, samples, dir, 1));
  std::filesystem::remove_all(dir);

  if (json) {
    for (const Row& r : rows) {
      std::printf(
          "{\"case\":\"%s\",\"path\":\"%s\",\"subscribers\":%d,\"rate_hz\":1000,\"events\":%zu,"
          "\"p50_us\":%.0f,\"p99_us\":%.0f,\"max_us\":%.0f,\"lost\":%llu,\"cpu_percent\":%.2f,"
          "\"rss_kb\":%ld}\n",
          r.name.c_str(), r.path.c_str(), r.subscribers, r.latency_us.n, r.latency_us.p50,
          r.latency_us.p99, r.latency_us.max, static_cast<unsigned long long>(r.lost),
          r.cpu_percent, r.rss_kb);
    }
    return 0;
  }
  std::printf(
      "sample emitted at 1 kHz -> subscriber receives (us); CPU %% of one core and RSS of "
      "the whole process (daemon + in-process clients)\n");
  std::printf("%-22s %-18s %5s %8s %8s %8s %8s %6s %8s %9s\n", "case", "path", "subs", "events",
              "p50_us", "p99_us", "max_us", "lost", "cpu_%", "rss_MB");
  for (const Row& r : rows) {
    std::printf("%-22s %-18s %5d %8zu %8.0f %8.0f %8.0f %6llu %8.2f %9.1f\n", r.name.c_str(),
                r.path.c_str(), r.subscribers, r.latency_us.n, r.latency_us.p50, r.latency_us.p99,
                r.latency_us.max, static_cast<unsigned long long>(r.lost), r.cpu_percent,
                static_cast<double>(r.rss_kb) / 1024.0);
  }
  return 0;
}
