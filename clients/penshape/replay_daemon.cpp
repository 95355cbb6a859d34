// `penshape replay` through penshaped: strokes decoded here, shapes certified by the daemon.
#include "replay_daemon.hpp"

#include <grpcpp/client_context.h>

#include <chrono>
#include <stdexcept>

#include "daemon_channel.hpp"

namespace penshape::cli {
namespace {

void fill_tablet(const TabletInfo& in, v1::TabletInfo* out) {
  out->set_bus(static_cast<v1::Bus>(static_cast<int>(in.bus)));
  out->set_vendor_id(in.vendor_id);
  out->set_product_id(in.product_id);
  out->set_name(in.name);
  out->set_x_max(in.x_max);
  out->set_y_max(in.y_max);
  out->set_pressure_max(in.pressure_max);
  out->set_x_resolution(in.x_resolution);
  out->set_y_resolution(in.y_resolution);
  out->set_has_tilt(in.has_tilt);
}

void fill_sample(const PenSample& in, v1::PenSample* out) {
  out->set_time_us(in.time_us);
  out->set_x(in.x);
  out->set_y(in.y);
  out->set_pressure(in.pressure);
  out->set_tilt_x(in.tilt_x);
  out->set_tilt_y(in.tilt_y);
  out->set_buttons(in.buttons);
  out->set_in_range(in.in_range);
  out->set_tip(in.tip);
}

} // namespace

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
  fill_tablet(tablet, request.mutable_stroke()->mutable_tablet());
  for (const PenSample& s : stroke.samples) {
    fill_sample(s, request.mutable_stroke()->add_samples());
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
