// An app's strokes added to their grouping on the stroke lane (app_grouping.hpp).
#include "app_grouping.hpp"

#include <chrono>

#include "call_runner.hpp"

namespace penshape::daemon {
namespace {

std::uint64_t micros_since(std::chrono::steady_clock::time_point t) {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - t)
          .count());
}

} // namespace

grpc::Status analyze_grouped(DaemonState& state, grpc::ServerContext* context,
                             GroupHistory& history, const Stroke& stroke,
                             const PenSettings& settings, GroupedStrokeAnalysis* out,
                             v1::Timings* timings) {
  if (!state.analyzer) {
    return {grpc::StatusCode::UNIMPLEMENTED,
            "stroke analysis: this server was built without the ink-polygon engine and "
            "recognizer"};
  }
  const auto arrived = std::chrono::steady_clock::now();
  std::uint64_t queued_us = 0;
  std::uint64_t compute_us = 0;
  const grpc::Status status = run_on_pool(
      state.stroke_pool, context, state.limits,
      [&](const StopCondition& stop) {
        const auto started = std::chrono::steady_clock::now();
        if (history.ensure(*state.analyzer, settings, state.grouping.get())) {
          *out = history.add(stroke, true, cancel_hook(stop));
        } else {
          out->analysis = state.analyzer->analyze(stroke, settings, cancel_hook(stop));
          out->grouped = false;
        }
        compute_us = micros_since(started);
        return grpc::Status::OK;
      },
      &queued_us);
  timings->set_queued_us(queued_us);
  timings->set_compute_us(compute_us);
  timings->set_total_us(micros_since(arrived));
  return status;
}

} // namespace penshape::daemon
