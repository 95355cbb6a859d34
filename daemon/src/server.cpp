#include "penshape/daemon/server.hpp"

#include <grpcpp/ext/proto_server_reflection_plugin.h>
#include <grpcpp/grpcpp.h>
#include <grpcpp/health_check_service_interface.h>

#include <cstdlib>
#include <stdexcept>

#include "info_service.hpp"

namespace penshape::daemon {

struct PenshapeServer::Impl {
  InfoServiceImpl info;
  std::unique_ptr<grpc::Server> server;
};

PenshapeServer::PenshapeServer(const ServerOptions& options) : impl_(std::make_unique<Impl>()) {
  grpc::EnableDefaultHealthCheckService(true);
  grpc::reflection::InitProtoReflectionServerBuilderPlugin();
  grpc::ServerBuilder builder;
  int bound_port = 0;
  builder.AddListeningPort(options.address, grpc::InsecureServerCredentials(), &bound_port);
  builder.RegisterService(&impl_->info);
  impl_->server = builder.BuildAndStart();
  if (!impl_->server) throw std::runtime_error("cannot listen on " + options.address);
}

PenshapeServer::~PenshapeServer() { shutdown(); }

void PenshapeServer::wait() { impl_->server->Wait(); }

void PenshapeServer::shutdown() {
  if (impl_->server) impl_->server->Shutdown();
}

std::string default_address() {
  const char* runtime = std::getenv("XDG_RUNTIME_DIR");
  const std::string dir = (runtime != nullptr && *runtime != '\0') ? runtime : "/tmp";
  return "unix:" + dir + "/penshape.sock";
}

} // namespace penshape::daemon
