#include "call_runner.hpp"

#include <future>
#include <new>

#include "penshape/daemon/geometry_backend.hpp"
#include "penshape/daemon/pen_settings.hpp"
#include "penshape/daemon/proto_convert.hpp"

namespace penshape::daemon {

StopCondition stop_condition_for(grpc::ServerContext* context, const Limits& limits) {
  using namespace std::chrono;
  const auto now_steady = steady_clock::now();
  auto deadline = now_steady + seconds(limits.max_call_seconds);
  const auto client_deadline = context->deadline();
  if (client_deadline != system_clock::time_point::max()) {
    // Compared as durations so a far-future deadline cannot overflow a time point.
    const auto remaining = client_deadline - system_clock::now();
    if (remaining < seconds(limits.max_call_seconds)) {
      deadline = now_steady + duration_cast<steady_clock::duration>(remaining);
    }
  }
  return StopCondition(deadline, [context] { return context->IsCancelled(); });
}

CancelHook cancel_hook(const StopCondition& stop) {
  return [&stop] { return stop.should_stop(); };
}

grpc::Status status_from_current_exception(const StopCondition* stop) {
  try {
    throw;
  } catch (const FieldError& e) {
    return {grpc::StatusCode::INVALID_ARGUMENT, e.what()};
  } catch (const SettingsError& e) {
    return {grpc::StatusCode::INVALID_ARGUMENT, e.what()};
  } catch (const InvalidInput& e) {
    return {grpc::StatusCode::INVALID_ARGUMENT, e.what()};
  } catch (const Cancelled&) {
    if (stop != nullptr && stop->deadline_passed() && !stop->cancelled()) {
      return {grpc::StatusCode::DEADLINE_EXCEEDED,
              "the call's deadline passed; computation stopped"};
    }
    return {grpc::StatusCode::CANCELLED, "cancelled by the client; computation stopped"};
  } catch (const NotAvailable& e) {
    return {grpc::StatusCode::UNIMPLEMENTED, e.what()};
  } catch (const std::bad_alloc&) {
    return {grpc::StatusCode::RESOURCE_EXHAUSTED, "out of memory for this request"};
  } catch (const std::exception& e) {
    return {grpc::StatusCode::INTERNAL, std::string("internal error: ") + e.what()};
  } catch (...) {
    return {grpc::StatusCode::INTERNAL, "internal error"};
  }
}

grpc::Status run_on_pool(WorkerPool& pool, grpc::ServerContext* context, const Limits& limits,
                         const std::function<grpc::Status(const StopCondition&)>& work,
                         std::uint64_t* queued_us) {
  const StopCondition stop = stop_condition_for(context, limits);
  std::promise<grpc::Status> done;
  std::future<grpc::Status> result = done.get_future();
  const auto submitted = std::chrono::steady_clock::now();
  const bool accepted = pool.submit(
      [&](const StopCondition& s) {
        if (queued_us != nullptr) {
          *queued_us =
              static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(
                                             std::chrono::steady_clock::now() - submitted)
                                             .count());
        }
        grpc::Status status;
        try {
          if (s.should_stop()) throw Cancelled();
          status = work(s);
        } catch (...) {
          status = status_from_current_exception(&s);
        }
        done.set_value(std::move(status));
      },
      stop);
  if (!accepted) {
    if (!pool.accepting()) {
      return {grpc::StatusCode::UNAVAILABLE, "the daemon is shutting down"};
    }
    return {grpc::StatusCode::RESOURCE_EXHAUSTED,
            "the geometry queue is full (limit worker_queue_jobs = " +
                std::to_string(limits.worker_queue_jobs) + "); retry later"};
  }
  // The job references this frame, so wait for it even after a cancellation: the job's own
  // CancelHook makes it end promptly.
  return result.get();
}

grpc::Status run_timed_on_pool(WorkerPool& pool, grpc::ServerContext* context, const Limits& limits,
                               std::chrono::steady_clock::time_point arrived,
                               const std::function<void(const StopCondition&)>& work,
                               v1::Timings* timings) {
  using Clock = std::chrono::steady_clock;
  const auto micros_since = [](Clock::time_point t) {
    return static_cast<std::uint64_t>(
        std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - t).count());
  };
  std::uint64_t queued_us = 0;
  std::uint64_t compute_us = 0;
  grpc::Status status = run_on_pool(
      pool, context, limits,
      [&](const StopCondition& stop) {
        const auto started = Clock::now();
        work(stop);
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
