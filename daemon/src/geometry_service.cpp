#include "geometry_service.hpp"

#include <chrono>
#include <cmath>
#include <optional>

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
  return run_timed_on_pool(
      state_.pool, context, state_.limits, arrived,
      [&](const StopCondition& stop) {
        deconstruct_into(
            *state_.geometry, q, params,
            {.simplify = request->simplify(), .include_offset = request->include_offset()},
            cancel_hook(stop), core_limits(state_.limits), response);
      },
      response->mutable_timings());
}

namespace {

// Progress of a search, streamed from the worker at most every kProgressPeriod.
template <typename Response>
class ProgressStream {
 public:
  static constexpr std::chrono::milliseconds kProgressPeriod{200};
  ProgressStream(grpc::ServerWriter<Response>* writer, Clock::time_point start, bool radius_search)
      : writer_(writer), start_(start), radius_search_(radius_search) {}

  // One decision: narrows the known bracket (YES above / NO below for tolerances; the other way
  // round for radii) and maybe writes a progress message.
  void decided(const DeconstructResult& r) {
    ++decisions_;
    const Rational& x = radius_search_ ? r.params.radius : r.params.tolerance;
    const bool raises_lower = radius_search_ ? r.answer == Answer::kYes : r.answer == Answer::kNo;
    const bool lowers_upper = radius_search_ ? r.answer == Answer::kNo : r.answer == Answer::kYes;
    if (raises_lower && (!lower_ || x > *lower_)) lower_ = x;
    if (lowers_upper && (!upper_ || x < *upper_)) upper_ = x;
    maybe_write(0);
  }
  void samples_done(std::size_t done, std::size_t total) {
    decisions_ = static_cast<std::uint32_t>(done);
    maybe_write(static_cast<std::uint32_t>(total));
  }

 private:
  void maybe_write(std::uint32_t estimate) {
    const auto now = Clock::now();
    if (now - last_ < kProgressPeriod) return;
    last_ = now;
    Response message;
    v1::SearchProgress* p = message.mutable_progress();
    p->set_decisions_done(decisions_);
    p->set_decisions_estimate(estimate);
    if (lower_) to_proto(*lower_, p->mutable_lower());
    if (upper_) to_proto(*upper_, p->mutable_upper());
    p->set_elapsed_us(micros_since(start_));
    writer_->Write(message); // a vanished client shows up as cancellation, checked by the core
  }

  grpc::ServerWriter<Response>* writer_;
  Clock::time_point start_;
  bool radius_search_;
  Clock::time_point last_ = Clock::now();
  std::uint32_t decisions_ = 0;
  std::optional<Rational> lower_;
  std::optional<Rational> upper_;
};

void to_proto_params(const DeconstructResult& r, v1::ResolvedParams* out) {
  to_proto(r.params.radius, out->mutable_radius());
  to_proto(r.params.tolerance, out->mutable_tolerance());
  to_proto(r.params.precision, out->mutable_precision());
  out->set_engine(to_proto(r.engine));
}

Rational positive(const v1::Scalar& s, bool present, const std::string& field,
                  const Limits& limits) {
  Rational v = scalar_from_proto(s, present, field, limits);
  if (sgn(v) <= 0) throw FieldError(field + " must be > 0");
  return v;
}

// What the search requests share: the polygon and the engine.
struct SearchInput {
  PolygonSet q;
  EngineKind engine = EngineKind::kFast;
};

// Validates a search request on the handler thread: the polygon, then the request's own fields
// (`fields`), then the engine. The status to answer at once (invalid, or no engine in this build),
// else OK.
template <typename Request, typename Fields>
grpc::Status read_search(const DaemonState& state, const Request& request, const char* rpc,
                         SearchInput& in, Fields fields) {
  grpc::Status status = validated([&] {
    in.q = polygon_set_from_proto(request.polygon(), "polygon", state.limits);
    fields();
    in.engine = engine_from_proto(request.engine(), "engine");
  });
  if (!status.ok()) return status;
  if (!state.geometry) return not_in_this_build(std::string(rpc) + ": no engine in this build");
  return grpc::Status::OK;
}

// Runs a streaming search on the geometry lane: progress messages while it runs (ProgressStream),
// then one last message with the result (filled by `compute`) and its timings.
template <typename Response, typename Compute>
grpc::Status run_search(DaemonState& state, grpc::ServerContext* context,
                        grpc::ServerWriter<Response>* writer, Clock::time_point arrived,
                        bool radius_search, Compute compute) {
  Response last;
  std::uint64_t queued_us = 0;
  grpc::Status status = run_on_pool(
      state.pool, context, state.limits,
      [&](const StopCondition& stop) {
        const auto started = Clock::now();
        ProgressStream<Response> progress(writer, arrived, radius_search);
        compute(stop, progress, last.mutable_result());
        last.mutable_result()->mutable_timings()->set_compute_us(micros_since(started));
        return grpc::Status::OK;
      },
      &queued_us);
  if (!status.ok()) return status;
  last.mutable_result()->mutable_timings()->set_queued_us(queued_us);
  last.mutable_result()->mutable_timings()->set_total_us(micros_since(arrived));
  writer->Write(last);
  return grpc::Status::OK;
}

} // namespace

grpc::Status GeometryServiceImpl::SearchTolerance(
    grpc::ServerContext* context, const v1::SearchToleranceRequest* request,
    grpc::ServerWriter<v1::SearchToleranceResponse>* writer) {
  const auto arrived = Clock::now();
  SearchInput in;
  Rational radius;
  Rational width;
  grpc::Status status = read_search(state_, *request, "SearchTolerance", in, [&] {
    radius = positive(request->radius(), request->has_radius(), "radius", state_.limits);
    width = positive(request->width(), request->has_width(), "width", state_.limits);
  });
  if (!status.ok()) return status;
  return run_search(
      state_, context, writer, arrived, false,
      [&](const StopCondition& stop, ProgressStream<v1::SearchToleranceResponse>& progress,
          v1::SearchToleranceResult* out) {
        const ToleranceSearchResult r = state_.geometry->search_tolerance(
            in.q, radius, width, in.engine, cancel_hook(stop), core_limits(state_.limits),
            [&](const DeconstructResult& d) { progress.decided(d); });
        to_proto(r.eps_low, out->mutable_lower());
        to_proto(r.eps_high, out->mutable_upper());
        to_proto(r.solution.solution, out->mutable_solution());
        to_proto_params(r.solution, out->mutable_params());
        out->set_converged(r.converged);
        out->set_note(r.note);
        out->set_decider_calls(r.decider_calls);
        out->set_fallback_calls(r.fallback_calls);
      });
}

grpc::Status GeometryServiceImpl::SearchRadius(
    grpc::ServerContext* context, const v1::SearchRadiusRequest* request,
    grpc::ServerWriter<v1::SearchRadiusResponse>* writer) {
  const auto arrived = Clock::now();
  SearchInput in;
  Rational tolerance;
  Rational width;
  std::optional<Rational> upper;
  grpc::Status status = read_search(state_, *request, "SearchRadius", in, [&] {
    tolerance =
        positive(request->tolerance(), request->has_tolerance(), "tolerance", state_.limits);
    width = positive(request->width(), request->has_width(), "width", state_.limits);
    if (request->has_max_radius()) {
      upper = positive(request->max_radius(), true, "max_radius", state_.limits);
    }
  });
  if (!status.ok()) return status;
  return run_search(
      state_, context, writer, arrived, true,
      [&](const StopCondition& stop, ProgressStream<v1::SearchRadiusResponse>& progress,
          v1::SearchRadiusResult* out) {
        const RadiusSearchResult r = state_.geometry->search_radius(
            in.q, tolerance, width, upper, in.engine, cancel_hook(stop), core_limits(state_.limits),
            [&](const DeconstructResult& d) { progress.decided(d); });
        to_proto(r.r_low, out->mutable_lower());
        to_proto(r.r_high, out->mutable_upper());
        to_proto(r.solution_at_low.solution, out->mutable_solution());
        to_proto_params(r.solution_at_low, out->mutable_params());
        out->set_converged(r.converged);
      });
}

grpc::Status GeometryServiceImpl::SuggestRadius(
    grpc::ServerContext* context, const v1::SuggestRadiusRequest* request,
    grpc::ServerWriter<v1::SuggestRadiusResponse>* writer) {
  const auto arrived = Clock::now();
  SearchInput in;
  SuggestOptions options;
  grpc::Status status = read_search(state_, *request, "SuggestRadius", in, [&] {
    options.from =
        positive(request->min_radius(), request->has_min_radius(), "min_radius", state_.limits);
    options.to = scalar_from_proto(request->max_radius(), request->has_max_radius(), "max_radius",
                                   state_.limits);
    if (options.to <= options.from) throw FieldError("max_radius must be > min_radius");
    if (request->samples() != 0 && (request->samples() < 3 || request->samples() > 256)) {
      throw FieldError("samples is " + std::to_string(request->samples()) +
                       ", outside [3, 256] (0 for the default 20)");
    }
    if (request->samples() != 0) options.samples = request->samples();
  });
  if (!status.ok()) return status;
  const std::size_t max_candidates = request->max_candidates() == 0 ? 3 : request->max_candidates();
  return run_search(
      state_, context, writer, arrived, true,
      [&](const StopCondition& stop, ProgressStream<v1::SuggestRadiusResponse>& progress,
          v1::SuggestRadiusResult* out) {
        options.progress = [&](std::size_t done, std::size_t total) {
          progress.samples_done(done, total);
          return !stop.should_stop();
        };
        const SuggestResult r = state_.geometry->suggest_radius(
            in.q, options, in.engine, cancel_hook(stop), core_limits(state_.limits));
        if (r.stopped_early) throw Cancelled();
        auto fill = [](const RadiusSample& sample, v1::RadiusCandidate* c) {
          to_proto(sample.radius, c->mutable_radius());
          to_proto(sample.eps_low, c->mutable_tolerance_lower());
          to_proto(sample.eps_high, c->mutable_tolerance_upper());
          c->set_score(sample.j);
        };
        for (std::size_t i = 0; i < r.suggestions.size() && i < max_candidates; ++i) {
          v1::RadiusCandidate* c = out->add_candidates();
          fill(r.suggestions[i].sample, c);
          to_proto(r.suggestions[i].solution.solution, c->mutable_solution());
        }
        for (const RadiusSample& sample : r.samples) fill(sample, out->add_samples());
      });
}

DeconstructLimits core_limits(const Limits& limits) {
  DeconstructLimits l;
  l.max_input_vertices = limits.max_vertices;
  return l;
}

void deconstruct_into(GeometryBackend& geometry, const PolygonSet& q,
                      const DeconstructParams& params, const DeconstructOptions& options,
                      const CancelHook& cancel, const DeconstructLimits& limits,
                      v1::DeconstructResponse* response) {
  DeconstructResult result = geometry.deconstruct(q, params, cancel, limits);
  const bool yes = result.answer == Answer::kYes;
  if (yes && options.simplify) {
    try {
      SimplifyResult simple = geometry.simplify(q, result, cancel, limits);
      v1::Simplification* info = response->mutable_simplification();
      info->set_simplified(simple.simplified);
      to_proto(simple.tau, info->mutable_tau());
      info->set_raw_vertices(static_cast<std::uint32_t>(simple.raw_vertices));
      info->set_solution_vertices(static_cast<std::uint32_t>(simple.solution_vertices));
      result = std::move(simple.result);
    } catch (const NotAvailable&) {
      if (!options.extras_if_available) throw;
    }
  }
  to_proto(result, response);
  if (yes && options.include_offset) {
    try {
      *response->mutable_solution_offset() =
          geometry.offset_boundary(result.solution, params.radius, cancel);
    } catch (const NotAvailable&) {
      if (!options.extras_if_available) throw;
    }
  }
}

grpc::Status analyze_stroke(DaemonState& state, grpc::ServerContext* context, const Stroke& stroke,
                            const PenSettings& settings, StrokeAnalysis* analysis,
                            v1::Timings* timings) {
  if (!state.analyzer) {
    return not_in_this_build(
        "stroke analysis: this server was built without the ink-polygon engine and recognizer");
  }
  return run_timed_on_pool(
      state.stroke_pool, context, state.limits, Clock::now(),
      [&](const StopCondition& stop) {
        *analysis = state.analyzer->analyze(stroke, settings, cancel_hook(stop));
      },
      timings);
}

namespace {

constexpr int kMaxGroupStrokes = 64;

GroupingConfig grouping_from_proto(const v1::GroupingSettings& g) {
  GroupingConfig out;
  if (g.has_disabled()) out.enabled = !g.disabled();
  if (g.has_max_strokes()) {
    if (g.max_strokes() < 1 || g.max_strokes() > 8) {
      throw InvalidInput("grouping.max_strokes must be within [1, 8]");
    }
    out.max_strokes = g.max_strokes();
  }
  if (g.has_max_pause_s()) {
    if (!(g.max_pause_s() >= 0) || !std::isfinite(g.max_pause_s())) {
      throw InvalidInput("grouping.max_pause_s must be a finite number >= 0");
    }
    out.max_pause_seconds = g.max_pause_s();
  }
  if (g.has_tidy_circle()) out.tidy.circle = g.tidy_circle();
  if (g.has_tidy_right_angles()) out.tidy.right_angles = g.tidy_right_angles();
  if (g.has_tidy_equal_sides()) out.tidy.equal_sides = g.tidy_equal_sides();
  if (g.has_tidy_axis()) out.tidy.axis = g.tidy_axis();
  if (g.has_tidy_parallel()) out.tidy.parallel = g.tidy_parallel();
  if (g.has_tidy_connection()) out.tidy.connection = g.tidy_connection();
  return out;
}

// Recognize with `strokes`: grouped on a stroke worker.
grpc::Status recognize_strokes_call(DaemonState& state, grpc::ServerContext* context,
                                    const v1::RecognizeRequest& request,
                                    v1::RecognizeResponse* response) {
  std::vector<Stroke> strokes;
  PenSettings settings;
  GroupingConfig grouping;
  grpc::Status status = validated([&] {
    if (request.has_stroke()) throw InvalidInput("give either `stroke` or `strokes`, not both");
    if (request.strokes_size() > kMaxGroupStrokes) {
      throw InvalidInput("strokes: at most " + std::to_string(kMaxGroupStrokes) + " strokes");
    }
    for (int i = 0; i < request.strokes_size(); ++i) {
      strokes.push_back(stroke_from_proto(request.strokes(i), "strokes[" + std::to_string(i) + "]",
                                          state.limits, true));
    }
    settings = apply(settings_for(state, strokes.front().tablet),
                     settings_update_from_proto(request.settings(), "settings"));
    grouping = grouping_from_proto(request.grouping());
  });
  if (!status.ok()) return status;
  if (!state.analyzer) {
    return not_in_this_build("recognize: this server was built without the recognizer");
  }
  const auto arrived = Clock::now();
  std::uint64_t queued_us = 0;
  std::uint64_t compute_us = 0;
  std::vector<v1::RecognizedGroup> groups;
  status = run_on_pool(
      state.stroke_pool, context, state.limits,
      [&](const StopCondition&) {
        const auto started = Clock::now();
        groups = state.analyzer->recognize_group(strokes, settings, grouping);
        compute_us = micros_since(started);
        return grpc::Status::OK;
      },
      &queued_us);
  if (!status.ok()) return status;
  if (groups.empty()) {
    return not_in_this_build("recognize: this server's analyzer does not recognize shapes");
  }
  for (auto& g : groups) *response->add_groups() = std::move(g);
  response->mutable_timings()->set_queued_us(queued_us);
  response->mutable_timings()->set_compute_us(compute_us);
  response->mutable_timings()->set_total_us(micros_since(arrived));
  return grpc::Status::OK;
}

} // namespace

grpc::Status GeometryServiceImpl::Recognize(grpc::ServerContext* context,
                                            const v1::RecognizeRequest* request,
                                            v1::RecognizeResponse* response) {
  if (request->strokes_size() > 0) {
    return recognize_strokes_call(state_, context, *request, response);
  }
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
