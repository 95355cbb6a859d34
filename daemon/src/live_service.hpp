#pragma once
#include "daemon_state.hpp"
#include "penshape/v1/live.grpc.pb.h"

namespace penshape::daemon {

// penshape.v1.Live: devices and live events through the hub; an app's own strokes through the
// StrokeAnalyzer.
class LiveServiceImpl final : public StateService<v1::Live::Service> {
 public:
  using StateService::StateService;

  grpc::Status ListDevices(grpc::ServerContext* context, const v1::ListDevicesRequest* request,
                           v1::ListDevicesResponse* response) override;
  grpc::Status WatchDevices(grpc::ServerContext* context, const v1::WatchDevicesRequest* request,
                            grpc::ServerWriter<v1::LiveEvent>* writer) override;
  grpc::Status Subscribe(grpc::ServerContext* context, const v1::SubscribeRequest* request,
                         grpc::ServerWriter<v1::LiveEvent>* writer) override;
  grpc::Status SubmitStroke(grpc::ServerContext* context, const v1::SubmitStrokeRequest* request,
                            v1::SubmitStrokeResponse* response) override;
  grpc::Status StreamSamples(
      grpc::ServerContext* context,
      grpc::ServerReaderWriter<v1::LiveEvent, v1::StreamSamplesRequest>* stream) override;

 private:
  // A hub subscription or the status refusing it (RESOURCE_EXHAUSTED / UNAVAILABLE).
  grpc::Status subscribe(EventFilter filter, std::size_t capacity,
                         std::unique_ptr<Subscription>* out);
  // SubmitStroke with a group_key: the stroke added to that key's grouping.
  grpc::Status submit_grouped(grpc::ServerContext* context, const v1::SubmitStrokeRequest& request,
                              const Stroke& stroke, const PenSettings& settings,
                              v1::SubmitStrokeResponse* response);
};

} // namespace penshape::daemon
