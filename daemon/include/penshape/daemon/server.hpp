#pragma once
// The penshaped gRPC server: its services (Info, Geometry, Live, Config, health, reflection) and
// the live pipeline behind them (sample source → worker pool → shape hub → subscribers).
#include <memory>
#include <string>
#include <vector>

#include "penshape/daemon/config.hpp"
#include "penshape/daemon/geometry_backend.hpp"
#include "penshape/daemon/sample_source.hpp"
#include "penshape/daemon/stroke_analyzer.hpp"

namespace grpc {
class Server;
}

namespace penshape::daemon {

class ShapeHub;
class WorkerPool;
class SettingsStore;

struct ServerOptions {
  // gRPC address: "unix:/path", "unix-abstract:name" or "127.0.0.1:port". A unix socket is made
  // owner-only (0600) and removed at shutdown.
  std::string address;
  // Limits, pen settings and an optional TCP address (config.tcp; config.listen is not used
  // here: the caller resolves it into `address`).
  DaemonConfig config;
};

// The pluggable parts; each may be null.
struct ServerParts {
  std::shared_ptr<SampleSource> source;      // null: no devices (the API still works)
  std::shared_ptr<GeometryBackend> geometry; // null: Deconstruct answers UNIMPLEMENTED
  std::shared_ptr<StrokeAnalyzer> analyzer;  // null: strokes carry no ink polygon or shape
};

// Builds and starts the server, then the sample source. Throws std::runtime_error when an address
// cannot be bound or another daemon already serves the unix socket.
class PenshapeServer {
 public:
  explicit PenshapeServer(const ServerOptions& options, ServerParts parts = {});
  ~PenshapeServer(); // shutdown()
  PenshapeServer(const PenshapeServer&) = delete;
  PenshapeServer& operator=(const PenshapeServer&) = delete;

  void wait(); // blocks until shutdown() has completed (call it from another thread)
  // Graceful and idempotent: stops the source (its strokes in progress finish), lets the workers
  // finish every accepted job, ends each subscription once its queue is delivered (streams end
  // with OK), then stops the server (calls still running after a 5 s grace are cancelled) and
  // removes the unix socket.
  void shutdown();

  [[nodiscard]] const std::vector<std::string>& addresses() const;
  ShapeHub& hub();
  WorkerPool& pool();
  SettingsStore& settings();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The default listening address: a unix socket in $XDG_RUNTIME_DIR (or /tmp when unset).
std::string default_address();

} // namespace penshape::daemon
