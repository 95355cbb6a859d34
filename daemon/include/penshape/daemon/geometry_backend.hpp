#pragma once
// What the Geometry service computes with. The real backend forwards to the core library
// (core_geometry_backend.cpp, linked when the engine is built); tests substitute their own.
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_set.hpp"
#include "penshape/core/search.hpp"
#include "penshape/core/simplify.hpp"
#include "penshape/v1/types.pb.h"

namespace penshape::daemon {

// Thrown for a computation this build does not contain; the service answers UNIMPLEMENTED
// with the message.
struct NotAvailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class GeometryBackend {
 public:
  virtual ~GeometryBackend() = default;
  // penshape::deconstruct() semantics: throws InvalidInput, Cancelled.
  virtual DeconstructResult deconstruct(const PolygonSet& q, const DeconstructParams& params,
                                        const CancelHook& cancel,
                                        const DeconstructLimits& limits) = 0;
  // The boundary of offset(p, radius) as segments and circular arcs (display doubles). Throws
  // NotAvailable unless the backend can compute it.
  virtual v1::CurvedRegion offset_boundary(const PolygonSet& p, const Rational& radius,
                                           const CancelHook& cancel);
  // simplify_solution() semantics (core/include/penshape/core/simplify.hpp): `raw` is a YES of
  // deconstruct(q, raw.params). Throws NotAvailable unless the backend can simplify.
  virtual SimplifyResult simplify(const PolygonSet& q, const DeconstructResult& raw,
                                  const CancelHook& cancel, const DeconstructLimits& limits);

  // The searches of core/include/penshape/core/search.hpp on q; `observe` sees every decision
  // (for progress). Throw NotAvailable unless the backend has them; InvalidInput, Cancelled.
  using DecisionObserver = std::function<void(const DeconstructResult&)>;
  virtual ToleranceSearchResult search_tolerance(const PolygonSet& q, const Rational& radius,
                                                 const Rational& width, EngineKind engine,
                                                 const CancelHook& cancel,
                                                 const DeconstructLimits& limits,
                                                 const DecisionObserver& observe);
  // upper_bound: a radius with no solution (absent: enclosing_radius_bound(q) + tolerance).
  virtual RadiusSearchResult search_radius(const PolygonSet& q, const Rational& tolerance,
                                           const Rational& width,
                                           const std::optional<Rational>& upper_bound,
                                           EngineKind engine, const CancelHook& cancel,
                                           const DeconstructLimits& limits,
                                           const DecisionObserver& observe);
  virtual SuggestResult suggest_radius(const PolygonSet& q, const SuggestOptions& options,
                                       EngineKind engine, const CancelHook& cancel,
                                       const DeconstructLimits& limits);
};

// The core library's engines (penshape::deconstruct). Defined in core_geometry_backend.cpp,
// which is compiled only when PENSHAPE_DAEMON_WITH_ENGINE is ON (the engine is linked).
std::unique_ptr<GeometryBackend> make_core_geometry_backend();

} // namespace penshape::daemon
