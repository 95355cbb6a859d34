#pragma once
// An app's own strokes (SubmitStroke with a group_key, a StreamSamples stream) added to their
// grouping on the stroke lane, as a tablet's live strokes are (live_grouping.hpp); analysers that
// do not group analyse the stroke alone.
#include <grpcpp/grpcpp.h>

#include "daemon_state.hpp"
#include "group_history.hpp"

namespace penshape::daemon {

// The stroke's ink polygon and grouped answer (out->grouped false when it was analysed alone),
// with the grouping window and tidy-up now in force (a change starts the grouping afresh). The
// caller then takes the answer's fields from `history` (take, remember). UNIMPLEMENTED without
// an analyzer; errors as run_on_pool.
grpc::Status analyze_grouped(DaemonState& state, grpc::ServerContext* context,
                             GroupHistory& history, const Stroke& stroke,
                             const PenSettings& settings, GroupedStrokeAnalysis* out,
                             v1::Timings* timings);

} // namespace penshape::daemon
