#pragma once
#include "daemon_state.hpp"
#include "penshape/v1/geometry.grpc.pb.h"

namespace penshape::daemon {

// penshape.v1.Geometry: Deconstruct on the GeometryBackend, Recognize on the StrokeAnalyzer. The
// searches validate their request and answer UNIMPLEMENTED until the core has them.
class GeometryServiceImpl final : public v1::Geometry::Service {
 public:
  explicit GeometryServiceImpl(DaemonState& state) : state_(state) {}

  grpc::Status Deconstruct(grpc::ServerContext* context, const v1::DeconstructRequest* request,
                           v1::DeconstructResponse* response) override;
  grpc::Status SearchTolerance(grpc::ServerContext* context,
                               const v1::SearchToleranceRequest* request,
                               grpc::ServerWriter<v1::SearchToleranceResponse>* writer) override;
  grpc::Status SearchRadius(grpc::ServerContext* context, const v1::SearchRadiusRequest* request,
                            grpc::ServerWriter<v1::SearchRadiusResponse>* writer) override;
  grpc::Status SuggestRadius(grpc::ServerContext* context, const v1::SuggestRadiusRequest* request,
                             grpc::ServerWriter<v1::SuggestRadiusResponse>* writer) override;
  grpc::Status Recognize(grpc::ServerContext* context, const v1::RecognizeRequest* request,
                         v1::RecognizeResponse* response) override;

 private:
  DaemonState& state_;
};

// Runs the analyzer for one stroke on the pool (SubmitStroke, Recognize, StreamSamples).
grpc::Status analyze_stroke(DaemonState& state, grpc::ServerContext* context, const Stroke& stroke,
                            const PenSettings& settings, StrokeAnalysis* analysis,
                            v1::Timings* timings);

} // namespace penshape::daemon
