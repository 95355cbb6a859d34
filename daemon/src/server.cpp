#include "penshape/daemon/server.hpp"

#include <grpcpp/ext/proto_server_reflection_plugin.h>
#include <grpcpp/grpcpp.h>
#include <grpcpp/health_check_service_interface.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "config_service.hpp"
#include "daemon_state.hpp"
#include "geometry_service.hpp"
#include "info_service.hpp"
#include "live_service.hpp"
#include "log.hpp"
#include "pipeline.hpp"
#include "thread_scheduling.hpp"
#include "unix_socket.hpp"

namespace penshape::daemon {
namespace {

constexpr std::chrono::seconds kShutdownGrace{5};
// A stream whose handler has returned still has its status to send: gRPC gets this long to send
// it before what is left is cancelled, so a subscriber that drained its queue ends with OK.
constexpr std::chrono::milliseconds kStatusDelivery{250};

} // namespace

struct PenshapeServer::Impl {
  Impl(const ServerOptions& options, ServerParts parts)
      : state(options.config.limits, options.config.settings, options.config.device_settings,
              options.config.grouping),
        pipeline(state),
        geometry(state),
        live(state),
        config(state),
        source(std::move(parts.source)) {
    state.geometry = std::move(parts.geometry);
    state.analyzer = std::move(parts.analyzer);
    addresses.push_back(options.address);
    if (!options.config.tcp.empty()) addresses.push_back(options.config.tcp);
  }

  // Destroyed in reverse: the server first (no handler runs), then the services and the state.
  DaemonState state;
  Pipeline pipeline;
  InfoServiceImpl info;
  GeometryServiceImpl geometry;
  LiveServiceImpl live;
  ConfigServiceImpl config;
  std::shared_ptr<SampleSource> source;
  std::vector<std::string> addresses;
  std::string socket_path;
  std::unique_ptr<grpc::Server> server;
  std::once_flag shutdown_once;
  std::mutex done_mutex;
  std::condition_variable done_cv;
  bool done = false;
};

PenshapeServer::PenshapeServer(const ServerOptions& options, ServerParts parts)
    : impl_(std::make_unique<Impl>(options, std::move(parts))) {
  // The threads created from here on (gRPC's, the sample source's readers) inherit a short time
  // slice, so that a sample is delivered within 1 ms even while strokes are analysed; the worker
  // lanes were created before and keep the default slice (thread_scheduling.hpp).
  request_short_slice_once();
  const Limits& limits = options.config.limits;
  impl_->socket_path = unix_socket_path(options.address);
  if (!impl_->socket_path.empty()) refuse_if_in_use(impl_->socket_path);

  grpc::EnableDefaultHealthCheckService(true);
  grpc::reflection::InitProtoReflectionServerBuilderPlugin();
  grpc::ServerBuilder builder;
  for (const std::string& address : impl_->addresses) {
    builder.AddListeningPort(address, grpc::InsecureServerCredentials());
  }
  builder.SetMaxReceiveMessageSize(static_cast<int>(limits.max_message_bytes));
  builder.RegisterService(&impl_->info);
  builder.RegisterService(&impl_->geometry);
  builder.RegisterService(&impl_->live);
  builder.RegisterService(&impl_->config);
  // The socket is created owner-only from the start (umask), not just chmod-ed afterwards.
  const mode_t previous_umask = ::umask(0077);
  impl_->server = builder.BuildAndStart();
  ::umask(previous_umask);
  if (!impl_->server) {
    std::string all;
    for (const auto& a : impl_->addresses) all += (all.empty() ? "" : ", ") + a;
    throw std::runtime_error("cannot listen on " + all);
  }
  try {
    if (!impl_->socket_path.empty()) make_owner_only(impl_->socket_path);
    if (impl_->source) impl_->source->start(impl_->pipeline);
  } catch (...) {
    // Not started: stop serving and leave no socket behind.
    impl_->state.hub.close();
    impl_->server->Shutdown(std::chrono::system_clock::now());
    impl_->server->Wait();
    if (!impl_->socket_path.empty()) ::unlink(impl_->socket_path.c_str());
    throw;
  }
}

PenshapeServer::~PenshapeServer() { shutdown(); }

void PenshapeServer::wait() {
  std::unique_lock lock(impl_->done_mutex);
  impl_->done_cv.wait(lock, [this] { return impl_->done; });
}

void PenshapeServer::shutdown() {
  std::call_once(impl_->shutdown_once, [this] {
    Impl& impl = *impl_;
    if (impl.source) {
      try {
        impl.source->stop(); // strokes in progress are finished into the pipeline
      } catch (const std::exception& e) {
        log(LogLevel::kError, std::string("stopping the sample source: ") + e.what());
      }
    }
    impl.pipeline.wait_idle(); // their analyses are published
    impl.state.hub.close();    // subscribers drain their queues, then end with OK
    // A grace period for streams to deliver their queues and geometry calls to finish; then the
    // rest is cancelled (their jobs see IsCancelled()). Shutdown(deadline) itself would also wait
    // for idle client connections until the deadline, so the long wait is done here and gRPC
    // gets only kStatusDelivery for the statuses of handlers that have just returned.
    const auto grace_end = std::chrono::steady_clock::now() + kShutdownGrace;
    const auto busy = [&impl] {
      return impl.state.pool.busy() + impl.state.stroke_pool.busy() +
             impl.state.preview_pool.busy();
    };
    while ((impl.state.hub.subscriber_count() > 0 || busy() > 0) &&
           std::chrono::steady_clock::now() < grace_end) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    impl.server->Shutdown(std::chrono::system_clock::now() + kStatusDelivery);
    impl.server->Wait();
    impl.state.pool.drain();
    impl.state.stroke_pool.drain();
    impl.state.preview_pool.drain();
    if (!impl.socket_path.empty()) ::unlink(impl.socket_path.c_str());
    {
      std::lock_guard lock(impl.done_mutex);
      impl.done = true;
    }
    impl.done_cv.notify_all();
  });
}

const std::vector<std::string>& PenshapeServer::addresses() const { return impl_->addresses; }
ShapeHub& PenshapeServer::hub() { return impl_->state.hub; }
WorkerPool& PenshapeServer::pool() { return impl_->state.pool; }
SettingsStore& PenshapeServer::settings() { return impl_->state.settings; }

std::string default_address() {
  const char* runtime = std::getenv("XDG_RUNTIME_DIR");
  const std::string dir = (runtime != nullptr && *runtime != '\0') ? runtime : "/tmp";
  return "unix:" + dir + "/penshape.sock";
}

} // namespace penshape::daemon
