#include "daemon_link.hpp"

#include <algorithm>
#include <cmath>

namespace penshape::board {

DaemonLink::DaemonLink(std::shared_ptr<grpc::Channel> channel, int width_px, int height_px,
                       EventHandler on_event, ErrorHandler on_error)
    : stub_(v1::Live::NewStub(std::move(channel))),
      on_event_(std::move(on_event)),
      on_error_(std::move(on_error)) {
  tablet_.set_name("penshape board");
  tablet_.set_x_max(width_px * kUnitsPerPixel);
  tablet_.set_y_max(height_px * kUnitsPerPixel);
  tablet_.set_pressure_max(1);
  tablet_.set_x_resolution(kUnitsPerPixel * kPixelsPerMm);
  tablet_.set_y_resolution(kUnitsPerPixel * kPixelsPerMm);
}

DaemonLink::~DaemonLink() { stop(); }

void DaemonLink::stop() {
  if (!stream_) return;
  {
    std::lock_guard lock(write_mutex_);
    stream_->WritesDone();
  }
  // The daemon finishes the stroke in progress and sends its results before ending the call.
  if (reader_.joinable()) reader_.join();
  const grpc::Status status = stream_->Finish();
  if (!status.ok() && status.error_code() != grpc::StatusCode::CANCELLED) {
    on_error_("StreamSamples: " + status.error_message());
  }
  stream_.reset();
  context_.reset();
}

void DaemonLink::start(double pen_radius_mm, double tolerance_fraction) {
  stop();
  context_ = std::make_unique<grpc::ClientContext>();
  stream_ = stub_->StreamSamples(context_.get());
  v1::StreamSamplesRequest first;
  *first.mutable_start()->mutable_tablet() = tablet_;
  first.mutable_start()->mutable_settings()->set_pen_radius_mm(pen_radius_mm);
  first.mutable_start()->mutable_settings()->set_tolerance_fraction(tolerance_fraction);
  first.mutable_start()->set_include_previews(true); // a guide of the shape while drawing
  stream_->Write(first);
  reader_ = std::thread([this] {
    v1::LiveEvent event;
    while (stream_->Read(&event)) on_event_(event);
  });
}

bool DaemonLink::send(float x, float y, bool tip, std::int64_t time_us) {
  if (!stream_) return false;
  v1::StreamSamplesRequest message;
  auto* s = message.mutable_samples()->add_samples();
  s->set_time_us(time_us);
  s->set_x(std::clamp(static_cast<int>(std::lround(x * kUnitsPerPixel)), 0, tablet_.x_max()));
  s->set_y(std::clamp(static_cast<int>(std::lround(y * kUnitsPerPixel)), 0, tablet_.y_max()));
  s->set_pressure(tip ? 1U : 0U);
  s->set_in_range(true);
  s->set_tip(tip);
  std::lock_guard lock(write_mutex_);
  return stream_->Write(message);
}

} // namespace penshape::board
