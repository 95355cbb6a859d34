// deconstruct(): validation (or a ValidatedRegion's parameters only), the r <= eps shortcut,
// dispatch to an engine, timing.
#include "penshape/core/deconstruct.hpp"

#include "penshape/core/convex_deconstruct.hpp"

#include <chrono>

#include "deconstruct/validate_input.hpp"
#include "engine/engines.hpp"
#include "engine/fast/fast_work.hpp"
#include "penshape/core/disk_approximation.hpp"
#include "penshape/core/validated_region.hpp"
#include "penshape/types/lookup_table.hpp"

namespace penshape {

const char* to_string(Answer a) {
  static constexpr LookupTable<Answer, const char*, 3> kAnswerNames{
      {{Answer::kYes, "YES"}, {Answer::kNo, "NO"}, {Answer::kUndecided, "UNDECIDED"}}};
  return lookup_or(kAnswerNames, a, "UNDECIDED");
}

const char* to_string(EngineKind e) { return e == EngineKind::kFast ? "fast" : "reference"; }

namespace {

// The fast engine, and the reference engine when the fast one stayed UNDECIDED because its grid
// lost a feature thinner than a grid unit. The result's `engine` names the one that answered.
// `keep` (optional) receives the fast engine's work when the fast engine answers.
DeconstructResult decide_default(const PolygonSet& q, const DeconstructParams& params,
                                 const CancelHook& cancel, const DeconstructLimits& limits,
                                 std::unique_ptr<detail::FastWork>* keep) {
  bool lost = false;
  // decide_valid() has oriented q: the engine need not check it again.
  DeconstructResult result = detail::decide_fast(q, params, cancel, limits, &lost, keep, true);
  if (result.answer != Answer::kUndecided || !lost) return result;
  if (keep != nullptr) keep->reset();
  DeconstructResult exact = detail::decide_reference(q, params, cancel, limits);
  exact.engine = EngineKind::kReference;
  return exact;
}

// Dispatch on oriented input with r > eps.
DeconstructResult decide(const PolygonSet& q, const DeconstructParams& params,
                         const CancelHook& cancel, const DeconstructLimits& limits,
                         std::unique_ptr<detail::FastWork>* keep) {
  if (params.engine == EngineKind::kReference) {
    DeconstructResult result = detail::decide_reference(q, params, cancel, limits);
    result.engine = EngineKind::kReference;
    return result;
  }
  if (is_convex_region(q)) {
    // Convex input: CONVEXDECIDE's linear path (Section 5), on the exact input.
    DeconstructResult result = convex_decide_simplified(q, params, cancel);
    result.engine = EngineKind::kFast;
    if (result.answer != Answer::kUndecided) return result;
  }
  return decide_default(q, params, cancel, limits, keep);
}

// Everything after validation; `start` is when the caller's call began.
DeconstructResult decide_valid(const PolygonSet& q, const DeconstructParams& params,
                               const CancelHook& cancel, const DeconstructLimits& limits,
                               std::chrono::steady_clock::time_point start,
                               std::unique_ptr<detail::FastWork>* keep = nullptr) {
  DeconstructResult result;
  if (params.radius <= params.tolerance) {
    // offset(Q, r) is r-close to Q and r <= eps: P = Q is a solution (paper, Section 2).
    result.answer = Answer::kYes;
    result.engine = params.engine;
    result.params = params;
    result.solution = q;
    normalize_orientation(result.solution);
    result.hausdorff_bound = params.radius;
  } else {
    // The engines want outer rings counterclockwise and holes clockwise: copy only to fix that.
    PolygonSet reoriented;
    const bool needs_fix = !has_normalized_orientation(q);
    if (needs_fix) {
      reoriented = q;
      normalize_orientation(reoriented);
    }
    const PolygonSet& oriented = needs_fix ? reoriented : q;
    result = decide(oriented, params, cancel, limits, keep);
    result.params = params;
  }
  result.elapsed = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::steady_clock::now() - start);
  return result;
}

} // namespace

DeconstructResult deconstruct(const PolygonSet& q, const DeconstructParams& params,
                              const CancelHook& cancel, const DeconstructLimits& limits) {
  const auto start = std::chrono::steady_clock::now();
  validate_deconstruct_input(q, params, limits, cancel);
  return decide_valid(q, params, cancel, limits, start);
}

DeconstructResult deconstruct(const ValidatedRegion& q, const DeconstructParams& params,
                              const CancelHook& cancel, const DeconstructLimits& limits) {
  std::unique_ptr<detail::FastWork> unused;
  return detail::deconstruct_keeping(q, params, cancel, limits, unused);
}

namespace detail {

DeconstructResult deconstruct_keeping(const ValidatedRegion& q, const DeconstructParams& params,
                                      const CancelHook& cancel, const DeconstructLimits& limits,
                                      std::unique_ptr<FastWork>& keep) {
  const auto start = std::chrono::steady_clock::now();
  validate_deconstruct_params(params, limits);
  // A spent token (its region released) holds an empty set.
  if (q.region().empty()) throw InvalidInput("the region is empty (no polygons)");
  check_vertex_limit(q.region(), limits.max_input_vertices);
  return decide_valid(q.region(), params, cancel, limits, start, &keep);
}

} // namespace detail

} // namespace penshape
