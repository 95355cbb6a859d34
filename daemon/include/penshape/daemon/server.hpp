#pragma once
// The penshaped gRPC server: its services, health and reflection, on one listening address.
#include <memory>
#include <string>

namespace grpc {
class Server;
}

namespace penshape::daemon {

struct ServerOptions {
  // gRPC address: "unix:/path", "unix-abstract:name" or "127.0.0.1:port".
  std::string address;
};

// Builds and starts the server; throws std::runtime_error when the address cannot be bound.
class PenshapeServer {
 public:
  explicit PenshapeServer(const ServerOptions& options);
  ~PenshapeServer();
  PenshapeServer(const PenshapeServer&) = delete;
  PenshapeServer& operator=(const PenshapeServer&) = delete;

  void wait();     // blocks until shutdown() is called from another thread
  void shutdown(); // stops accepting, finishes in-flight calls

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The default listening address: a unix socket in $XDG_RUNTIME_DIR (or /tmp when unset).
std::string default_address();

} // namespace penshape::daemon
