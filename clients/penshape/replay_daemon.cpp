// `penshape replay` through penshaped: strokes decoded here, shapes certified by the daemon.
#include "replay_daemon.hpp"

#include <grpcpp/client_context.h>

#include <chrono>
#include <stdexcept>

#include "daemon_channel.hpp"
#include "penshape/proto/pen_types.hpp"

namespace penshape::cli {
std::optional<ReplayDaemon> ReplayDaemon::connect(const std::string& address, std::string& why) {
  try {
    return ReplayDaemon(v1::Live::NewStub(connect_to_daemon(address, std::chrono::seconds(1))),
                        address);
  } catch (const DaemonUnavailable& e) {
    why = e.what();
    return std::nullopt;
  }
}

v1::Shape ReplayDaemon::recognize(const Stroke& stroke, const TabletInfo& tablet) {
  v1::SubmitStrokeRequest request;
  request.mutable_stroke()->set_id(stroke.id);
  proto::to_proto(tablet, request.mutable_stroke()->mutable_tablet());
  for (const PenSample& s : stroke.samples) {
    proto::to_proto(s, request.mutable_stroke()->add_samples());
  }
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(30));
  v1::SubmitStrokeResponse response;
  const grpc::Status status = stub_->SubmitStroke(&context, request, &response);
  if (!status.ok()) {
    throw std::runtime_error(describe_rpc_failure(status, "SubmitStroke", address_).message);
  }
  return response.shape();
}

} // namespace penshape::cli
