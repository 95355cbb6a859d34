#pragma once
// Runs the heavy part of an RPC on the geometry worker pool and maps its outcome to a status.
// The handler thread waits; the job's CancelHook checks ServerContext::IsCancelled() and the
// call's deadline (the client's, cut to limits.max_call_seconds), so long work stops promptly.
#include <grpcpp/grpcpp.h>

#include <chrono>
#include <functional>

#include "penshape/core/deconstruct.hpp"
#include "penshape/daemon/limits.hpp"
#include "penshape/daemon/worker_pool.hpp"
#include "penshape/v1/types.pb.h"

namespace penshape::daemon {

// The stop condition of a call: the client's deadline cut to the server's limit, and the
// client's cancellation.
StopCondition stop_condition_for(grpc::ServerContext* context, const Limits& limits);

// A CancelHook for the core from a stop condition.
CancelHook cancel_hook(const StopCondition& stop);

// Runs `work` on the pool and waits for it. Exceptions become statuses: FieldError, InvalidInput
// and SettingsError → INVALID_ARGUMENT; Cancelled → CANCELLED or DEADLINE_EXCEEDED; NotAvailable
// → UNIMPLEMENTED; std::bad_alloc → RESOURCE_EXHAUSTED; anything else → INTERNAL. A full queue is
// RESOURCE_EXHAUSTED, a draining pool UNAVAILABLE. `queued_us` receives the time spent waiting.
grpc::Status run_on_pool(WorkerPool& pool, grpc::ServerContext* context, const Limits& limits,
                         const std::function<grpc::Status(const StopCondition&)>& work,
                         std::uint64_t* queued_us = nullptr);

// run_on_pool for work that cannot fail other than by throwing, filling `timings`: the time
// queued, the work's own time and the total since `arrived` (when the call came in).
grpc::Status run_timed_on_pool(WorkerPool& pool, grpc::ServerContext* context, const Limits& limits,
                               std::chrono::steady_clock::time_point arrived,
                               const std::function<void(const StopCondition&)>& work,
                               v1::Timings* timings);

// The same mapping for exceptions thrown on the handler thread itself.
grpc::Status status_from_current_exception(const StopCondition* stop);

} // namespace penshape::daemon
