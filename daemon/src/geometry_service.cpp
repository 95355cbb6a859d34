#include "geometry_service.hpp"

#include <chrono>

#include "call_runner.hpp"
#include "penshape/daemon/proto_convert.hpp"

namespace penshape::daemon {
namespace {

using Clock = std::chrono::steady_clock;

std::uint64_t micros_since(Clock::time_point start) {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start).count());
}

// Validates on the handler thread (cheap, and a bad request never takes a worker).
template <typename F>
grpc::Status validated(F&& f) {
  try {
    f();
    return grpc::Status::OK;
  } catch (...) {
    return status_from_current_exception(nullptr);
  }
}

grpc::Status not_in_this_build(const std::string& what) {
  return {grpc::StatusCode::UNIMPLEMENTED, what};
}

} // namespace

grpc::Status GeometryServiceImpl::Deconstruct(grpc::ServerContext* context,
                                              const v1::DeconstructRequest* request,
                                              v1::DeconstructResponse* response) {
  const auto arrived = Clock::now();
  PolygonSet q;
  DeconstructParams params;
  grpc::Status status = validated([&] {
    q = polygon_set_from_proto(request->polygon(), "polygon", state_.limits);
    params = deconstruct_params_from_proto(*request, state_.limits);
  });
  if (!status.ok()) return status;
  if (!state_.geometry) {
    return not_in_this_build(
        "Deconstruct: this server was built without the deconstruction engine "
        "(PENSHAPE_DAEMON_WITH_ENGINE=OFF)");
  }
  std::uint64_t queued_us = 0;
  std::uint64_t compute_us = 0;
  status = run_on_pool(
      state_.pool, context, state_.limits,
      [&](const StopCondition& stop) {
        const auto started = Clock::now();
        DeconstructLimits limits;
        limits.max_input_vertices = state_.limits.max_vertices;
        const CancelHook hook = cancel_hook(stop);
        const DeconstructResult result = state_.geometry->deconstruct(q, params, hook, limits);
        to_proto(result, response);
        if (request->include_offset() && result.answer == Answer::kYes) {
          *response->mutable_solution_offset() =
              state_.geometry->offset_boundary(result.solution, params.radius, hook);
        }
        compute_us = micros_since(started);
        return grpc::Status::OK;
      },
      &queued_us);
  if (!status.ok()) return status;
  v1::Timings* timings = response->mutable_timings();
  timings->set_queued_us(queued_us);
  timings->set_compute_us(compute_us);
  timings->set_total_us(micros_since(arrived));
  return grpc::Status::OK;
}

grpc::Status GeometryServiceImpl::SearchTolerance(
    grpc::ServerContext* /*context*/, const v1::SearchToleranceRequest* request,
    grpc::ServerWriter<v1::SearchToleranceResponse>* /*writer*/) {
  const grpc::Status status = validated([&] {
    polygon_set_from_proto(request->polygon(), "polygon", state_.limits);
    if (sgn(scalar_from_proto(request->radius(), request->has_radius(), "radius", state_.limits)) <=
        0) {
      throw FieldError("radius must be > 0");
    }
    if (sgn(scalar_from_proto(request->width(), request->has_width(), "width", state_.limits)) <=
        0) {
      throw FieldError("width must be > 0");
    }
    engine_from_proto(request->engine(), "engine");
  });
  if (!status.ok()) return status;
  return not_in_this_build(
      "SearchTolerance: the tolerance search (APPROXSEARCHEPS) is not in this build yet; "
      "Deconstruct decides one tolerance at a time");
}

grpc::Status GeometryServiceImpl::SearchRadius(
    grpc::ServerContext* /*context*/, const v1::SearchRadiusRequest* request,
    grpc::ServerWriter<v1::SearchRadiusResponse>* /*writer*/) {
  const grpc::Status status = validated([&] {
    polygon_set_from_proto(request->polygon(), "polygon", state_.limits);
    if (sgn(scalar_from_proto(request->tolerance(), request->has_tolerance(), "tolerance",
                              state_.limits)) <= 0) {
      throw FieldError("tolerance must be > 0");
    }
    if (sgn(scalar_from_proto(request->width(), request->has_width(), "width", state_.limits)) <=
        0) {
      throw FieldError("width must be > 0");
    }
    if (request->has_max_radius() &&
        sgn(scalar_from_proto(request->max_radius(), true, "max_radius", state_.limits)) <= 0) {
      throw FieldError("max_radius must be > 0");
    }
    engine_from_proto(request->engine(), "engine");
  });
  if (!status.ok()) return status;
  return not_in_this_build(
      "SearchRadius: the radius search is not in this build yet; Deconstruct decides one radius "
      "at a time");
}

grpc::Status GeometryServiceImpl::SuggestRadius(
    grpc::ServerContext* /*context*/, const v1::SuggestRadiusRequest* request,
    grpc::ServerWriter<v1::SuggestRadiusResponse>* /*writer*/) {
  const grpc::Status status = validated([&] {
    polygon_set_from_proto(request->polygon(), "polygon", state_.limits);
    const Rational lo = scalar_from_proto(request->min_radius(), request->has_min_radius(),
                                          "min_radius", state_.limits);
    const Rational hi = scalar_from_proto(request->max_radius(), request->has_max_radius(),
                                          "max_radius", state_.limits);
    if (sgn(lo) <= 0) throw FieldError("min_radius must be > 0");
    if (hi <= lo) throw FieldError("max_radius must be > min_radius");
    if (request->samples() != 0 && (request->samples() < 2 || request->samples() > 256)) {
      throw FieldError("samples is " + std::to_string(request->samples()) +
                       ", outside [2, 256] (0 for the default 32)");
    }
    engine_from_proto(request->engine(), "engine");
  });
  if (!status.ok()) return status;
  return not_in_this_build(
      "SuggestRadius: the radius suggestion (maxima of r / eps^(r)) is not in this build yet");
}

grpc::Status analyze_stroke(DaemonState& state, grpc::ServerContext* context, const Stroke& stroke,
                            const PenSettings& settings, StrokeAnalysis* analysis,
                            v1::Timings* timings) {
  if (!state.analyzer) {
    return not_in_this_build(
        "stroke analysis: this server was built without the ink-polygon engine and recognizer");
  }
  const auto arrived = Clock::now();
  std::uint64_t queued_us = 0;
  std::uint64_t compute_us = 0;
  const grpc::Status status = run_on_pool(
      state.pool, context, state.limits,
      [&](const StopCondition& stop) {
        const auto started = Clock::now();
        *analysis = state.analyzer->analyze(stroke, settings, cancel_hook(stop));
        compute_us = micros_since(started);
        return grpc::Status::OK;
      },
      &queued_us);
  timings->set_queued_us(queued_us);
  timings->set_compute_us(compute_us);
  timings->set_total_us(micros_since(arrived));
  return status;
}

grpc::Status GeometryServiceImpl::Recognize(grpc::ServerContext* context,
                                            const v1::RecognizeRequest* request,
                                            v1::RecognizeResponse* response) {
  Stroke stroke;
  PenSettings settings;
  grpc::Status status = validated([&] {
    stroke = stroke_from_proto(request->stroke(), "stroke", state_.limits, true);
    settings = apply(settings_for(state_, stroke.tablet),
                     settings_update_from_proto(request->settings(), "settings"));
  });
  if (!status.ok()) return status;
  StrokeAnalysis analysis;
  status =
      analyze_stroke(state_, context, stroke, settings, &analysis, response->mutable_timings());
  if (!status.ok()) return status;
  *response->mutable_shape() = std::move(analysis.shape);
  for (auto& alternative : analysis.alternatives) *response->add_alternatives() = alternative;
  *response->mutable_ink_polygon() = std::move(analysis.ink_polygon);
  return grpc::Status::OK;
}

} // namespace penshape::daemon
