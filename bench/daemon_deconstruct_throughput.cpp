// Unary Deconstruct throughput through the real daemon with 1, 8 and 64 concurrent gRPC clients,
// beside the baseline: the same backend called directly in process (proto conversion included),
// one thread. The polygon is the authors' S (23 vertices, shared data).
//
// With PENSHAPE_DAEMON_WITH_ENGINE the backend is the core engine (r = 10, eps = 5). Without it,
// the case r <= eps is used (r = eps = 5), where the contract's answer is YES with P = Q, so the
// figures are the daemon's own cost per call: conversions, the worker pool, gRPC.
//
//   build/release/bench/daemon_deconstruct_throughput [--seconds 2] [--json]
#include <grpcpp/grpcpp.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_data.hpp"
#include "bench_support.hpp"
#include "penshape/daemon/geometry_backend.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/v1/geometry.grpc.pb.h"

namespace {

namespace v1 = penshape::v1;
using Clock = std::chrono::steady_clock;

#ifndef PENSHAPE_DAEMON_WITH_ENGINE
// APPROXDECIDE for r <= eps: YES with P = Q (deconstruct.hpp); other inputs are not used here.
class TrivialCaseBackend final : public penshape::daemon::GeometryBackend {
 public:
  penshape::DeconstructResult deconstruct(const penshape::PolygonSet& q,
                                          const penshape::DeconstructParams& params,
                                          const penshape::CancelHook& /*cancel*/,
                                          const penshape::DeconstructLimits& /*limits*/) override {
    if (params.radius > params.tolerance) throw penshape::InvalidInput("needs r <= eps");
    penshape::DeconstructResult result;
    result.answer = penshape::Answer::kYes;
    result.engine = params.engine;
    result.params = params;
    result.solution = q;
    result.hausdorff_bound = params.radius;
    return result;
  }
};
#endif

std::shared_ptr<penshape::daemon::GeometryBackend> backend() {
#ifdef PENSHAPE_DAEMON_WITH_ENGINE
  return penshape::daemon::make_core_geometry_backend();
#else
  return std::make_shared<TrivialCaseBackend>();
#endif
}

v1::DeconstructRequest request() {
  const std::string file = penshape::bench::shared_data_dir() + "/polygons/authors_S.txt";
  penshape::bench::say_data("daemon_deconstruct_throughput", file);
  std::ifstream in(file);
  v1::DeconstructRequest r;
  auto* ring = r.mutable_polygon()->add_polygons()->mutable_outer();
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double x = 0, y = 0;
    fields >> x >> y;
    auto* p = ring->add_points();
    p->set_x(x);
    p->set_y(y);
  }
#ifdef PENSHAPE_DAEMON_WITH_ENGINE
  r.mutable_radius()->set_value(10);
#else
  r.mutable_radius()->set_value(5);
#endif
  r.mutable_tolerance()->set_value(5);
  return r;
}

struct Row {
  std::string name;
  int clients = 0;
  std::size_t calls = 0;
  std::size_t failures = 0;
  double per_second = 0;
  double p50_us = 0, p99_us = 0;
};

Row direct(const v1::DeconstructRequest& req, double seconds) {
  auto b = backend();
  const penshape::daemon::Limits limits;
  Row row{"baseline: direct call", 1, 0, 0, 0, 0, 0};
  std::vector<double> latencies;
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  const auto t0 = Clock::now();
  while (Clock::now() < end) {
    const auto s = Clock::now();
    const auto q = penshape::daemon::polygon_set_from_proto(req.polygon(), "polygon", limits);
    const auto params = penshape::daemon::deconstruct_params_from_proto(req, limits);
    v1::DeconstructResponse response;
    penshape::daemon::to_proto(b->deconstruct(q, params, {}, {}), &response);
    latencies.push_back(std::chrono::duration<double, std::micro>(Clock::now() - s).count());
  }
  row.calls = latencies.size();
  row.per_second =
      static_cast<double>(row.calls) / std::chrono::duration<double>(Clock::now() - t0).count();
  const auto p = penshape::bench::percentiles(latencies);
  row.p50_us = p.p50;
  row.p99_us = p.p99;
  return row;
}

Row through_daemon(const v1::DeconstructRequest& req, int clients, double seconds,
                   const std::string& address) {
  Row row{"gRPC Deconstruct", clients, 0, 0, 0, 0, 0};
  std::vector<std::vector<double>> latencies(static_cast<std::size_t>(clients));
  std::atomic<std::size_t> failures{0};
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  const auto t0 = Clock::now();
  std::vector<std::thread> threads;
  threads.reserve(static_cast<std::size_t>(clients));
  for (int c = 0; c < clients; ++c) {
    threads.emplace_back([&, c] {
      // One channel per client, as separate programs would have.
      grpc::ChannelArguments args;
      args.SetInt("bench.client", c);
      auto stub = v1::Geometry::NewStub(
          grpc::CreateCustomChannel(address, grpc::InsecureChannelCredentials(), args));
      while (Clock::now() < end) {
        grpc::ClientContext ctx;
        v1::DeconstructResponse response;
        const auto s = Clock::now();
        if (!stub->Deconstruct(&ctx, req, &response).ok()) {
          ++failures;
          continue;
        }
        latencies[static_cast<std::size_t>(c)].push_back(
            std::chrono::duration<double, std::micro>(Clock::now() - s).count());
      }
    });
  }
  for (auto& t : threads) t.join();
  std::vector<double> all;
  for (auto& l : latencies) all.insert(all.end(), l.begin(), l.end());
  row.calls = all.size();
  row.failures = failures;
  row.per_second =
      static_cast<double>(row.calls) / std::chrono::duration<double>(Clock::now() - t0).count();
  const auto p = penshape::bench::percentiles(all);
  row.p50_us = p.p50;
  row.p99_us = p.p99;
  return row;
}

} // namespace

int main(int argc, char** argv) {
  const auto args =
      penshape::bench::parse_seconds_args(argc, argv, "daemon_deconstruct_throughput", 2);
  if (!args) return 2;
  const double seconds = args->seconds;
  const bool json = args->json;
  const std::string dir = penshape::bench::make_scratch_dir();
  const v1::DeconstructRequest req = request();
  penshape::daemon::ServerOptions options;
  options.address = "unix:" + dir + "/bench.sock";
  options.config.limits.worker_queue_jobs = 256; // 64 clients never see a full queue
  std::vector<Row> rows;
  {
    penshape::daemon::PenshapeServer server(options, {nullptr, backend(), nullptr});
    rows.push_back(direct(req, seconds));
    for (int clients : {1, 8, 64})
      rows.push_back(through_daemon(req, clients, seconds, options.address));
  }
  std::filesystem::remove_all(dir);
#ifdef PENSHAPE_DAEMON_WITH_ENGINE
  const char* engine = "core engine, S polygon, r=10 eps=5";
#else
  const char* engine = "r <= eps (P = Q): the daemon's own cost, S polygon, r=eps=5";
#endif
  if (json) {
    for (const Row& r : rows) {
      std::printf(
          "{\"case\":\"%s\",\"engine\":\"%s\",\"clients\":%d,\"calls\":%zu,\"failures\":%zu,"
          "\"calls_per_s\":%.1f,\"p50_us\":%.0f,\"p99_us\":%.0f}\n",
          r.name.c_str(), engine, r.clients, r.calls, r.failures, r.per_second, r.p50_us, r.p99_us);
    }
    return 0;
  }
  std::printf("Deconstruct throughput (%s)\n", engine);
  std::printf("%-24s %8s %8s %9s %11s %8s %8s\n", "case", "clients", "calls", "failures", "calls/s",
              "p50_us", "p99_us");
  for (const Row& r : rows) {
    std::printf("%-24s %8d %8zu %9zu %11.1f %8.0f %8.0f\n", r.name.c_str(), r.clients, r.calls,
                r.failures, r.per_second, r.p50_us, r.p99_us);
  }
  return 0;
}
