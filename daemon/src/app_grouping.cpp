// An app's strokes added to their grouping on the stroke lane (app_grouping.hpp).
#include "app_grouping.hpp"

#include <chrono>

#include "call_runner.hpp"

namespace penshape::daemon {

grpc::Status analyze_grouped(DaemonState& state, grpc::ServerContext* context,
                             GroupHistory& history, const Stroke& stroke,
                             const PenSettings& settings, GroupedStrokeAnalysis* out,
                             v1::Timings* timings) {
  if (!state.analyzer) {
    return {grpc::StatusCode::UNIMPLEMENTED,
            "stroke analysis: this server was built without the ink-polygon engine and "
            "recognizer"};
  }
  return run_timed_on_pool(
      state.stroke_pool, context, state.limits, std::chrono::steady_clock::now(),
      [&](const StopCondition& stop) {
        if (history.ensure(*state.analyzer, settings, state.grouping.get())) {
          *out = history.add(stroke, true, cancel_hook(stop), ink_offload(state.stroke_pool));
        } else {
          out->analysis = state.analyzer->analyze(stroke, settings, cancel_hook(stop));
          out->grouped = false;
        }
      },
      timings);
}

} // namespace penshape::daemon
