#pragma once
#include "daemon_state.hpp"
#include "penshape/v1/geometry.grpc.pb.h"

namespace penshape::daemon {

// penshape.v1.Geometry: Deconstruct on the GeometryBackend, Recognize on the StrokeAnalyzer. The
// searches validate their request and answer UNIMPLEMENTED until the core has them.
class GeometryServiceImpl final : public StateService<v1::Geometry::Service> {
 public:
  using StateService::StateService;

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
};

// The core's limits from the daemon's (max_vertices).
DeconstructLimits core_limits(const Limits& limits);

// One deconstruction into its response (the Deconstruct RPC and the live StrokeDeconstructed
// event): decide, then with YES simplify (when asked) and add the offset's boundary (when asked).
// Timings are left to the caller. Throws what the backend throws.
struct DeconstructOptions {
  bool simplify = false;
  bool include_offset = false;
  // A backend that cannot simplify or draw offsets (NotAvailable) leaves them out instead of
  // failing the call (the live event: the certified raw P is still worth sending).
  bool extras_if_available = false;
};
void deconstruct_into(GeometryBackend& geometry, const PolygonSet& q,
                      const DeconstructParams& params, const DeconstructOptions& options,
                      const CancelHook& cancel, const DeconstructLimits& limits,
                      v1::DeconstructResponse* response);

// Runs the analyzer for one stroke on the pool (SubmitStroke, Recognize, StreamSamples).
grpc::Status analyze_stroke(DaemonState& state, grpc::ServerContext* context, const Stroke& stroke,
                            const PenSettings& settings, StrokeAnalysis* analysis,
                            v1::Timings* timings);

} // namespace penshape::daemon
