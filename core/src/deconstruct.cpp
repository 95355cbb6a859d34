// deconstruct(): validation, the r <= eps shortcut, dispatch to an engine, timing.
#include "penshape/core/deconstruct.hpp"

#include "penshape/core/convex_deconstruct.hpp"

#include <chrono>

#include "engine/engines.hpp"
#include "penshape/core/disk_approximation.hpp"

namespace penshape {

const char* to_string(Answer a) {
  switch (a) {
    case Answer::kYes:
      return "YES";
    case Answer::kNo:
      return "NO";
    case Answer::kUndecided:
      break;
  }
  return "UNDECIDED";
}

const char* to_string(EngineKind e) { return e == EngineKind::kFast ? "fast" : "reference"; }

DeconstructResult deconstruct(const PolygonSet& q, const DeconstructParams& params,
                              const CancelHook& cancel, const DeconstructLimits& limits) {
  const auto start = std::chrono::steady_clock::now();
  validate_deconstruct_input(q, params, limits, cancel);
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
    if (params.engine == EngineKind::kReference) {
      result = detail::decide_reference(oriented, params, cancel, limits);
    } else if (is_convex_region(oriented)) {
      // Convex input: CONVEXDECIDE's linear path (Section 5), on the exact input.
      result = convex_decide_simplified(oriented, params, cancel);
      if (result.answer == Answer::kUndecided) {
        result = detail::decide_fast(oriented, params, cancel, limits);
      }
    } else {
      result = detail::decide_fast(oriented, params, cancel, limits);
    }
    result.engine = params.engine;
    result.params = params;
  }
  result.elapsed = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::steady_clock::now() - start);
  return result;
}

} // namespace penshape
