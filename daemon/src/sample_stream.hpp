#pragma once
// One StreamSamples call (live.proto): an app's own pen samples, cut into strokes (tip down to tip
// up, the segmenter's rule for one pen), each analysed and grouped with the stream's earlier
// strokes, with hold to snap and previews as its StreamStart asks; the answers go back on the
// same stream, never through the hub.
#include <grpcpp/grpcpp.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "daemon_state.hpp"
#include "group_history.hpp"
#include "penshape/v1/live.grpc.pb.h"
#include "stream_hold.hpp"

namespace penshape::daemon {

class SampleStream {
 public:
  using Stream = grpc::ServerReaderWriter<v1::LiveEvent, v1::StreamSamplesRequest>;
  SampleStream(DaemonState& state, grpc::ServerContext* context, Stream* stream)
      : state_(state), context_(context), stream_(stream) {}
  // Reads the StreamStart, then every batch, until the client finishes sending (a stroke still
  // down ends there) or an error (INVALID_ARGUMENT naming the field) or a lost client.
  grpc::Status run();

 private:
  grpc::Status start(const v1::StreamSamplesRequest& first);
  grpc::Status add_batch(const v1::StreamSamplesRequest& message, std::size_t batch_index);
  grpc::Status add_sample(const PenSample& sample, const std::string& at);
  bool begin_stroke();
  grpc::Status finish_stroke();
  bool write_shape(GroupedStrokeAnalysis& result, const v1::Timings& timings, std::uint64_t id);
  bool maybe_preview();
  bool write(v1::LiveEvent event);

  DaemonState& state_;
  grpc::ServerContext* context_;
  Stream* stream_;
  TabletInfo tablet_;
  PenSettings settings_;
  bool previews_ = false;
  std::chrono::steady_clock::time_point last_preview_{};
  std::optional<Stroke> current_; // the stroke while the tip is down
  std::int64_t last_time_ = INT64_MIN;
  GroupHistory grouping_; // the stream's strokes group with each other only
  std::optional<StreamHold> hold_;
};

} // namespace penshape::daemon
