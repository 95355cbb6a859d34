#include "penshape/daemon/geometry_backend.hpp"

namespace penshape::daemon {

v1::CurvedRegion GeometryBackend::offset_boundary(const PolygonSet& /*p*/,
                                                  const Rational& /*radius*/,
                                                  const CancelHook& /*cancel*/) {
  throw NotAvailable(
      "include_offset: this server's geometry backend cannot compute offset boundaries with arcs");
}

SimplifyResult GeometryBackend::simplify(const PolygonSet& /*q*/, const DeconstructResult& /*raw*/,
                                         const CancelHook& /*cancel*/,
                                         const DeconstructLimits& /*limits*/) {
  throw NotAvailable("simplify: this server's geometry backend cannot simplify solutions");
}

ToleranceSearchResult GeometryBackend::search_tolerance(const PolygonSet&, const Rational&,
                                                        const Rational&, EngineKind,
                                                        const CancelHook&, const DeconstructLimits&,
                                                        const DecisionObserver&) {
  throw NotAvailable("SearchTolerance: this server's geometry backend has no tolerance search");
}

RadiusSearchResult GeometryBackend::search_radius(const PolygonSet&, const Rational&,
                                                  const Rational&, const std::optional<Rational>&,
                                                  EngineKind, const CancelHook&,
                                                  const DeconstructLimits&,
                                                  const DecisionObserver&) {
  throw NotAvailable("SearchRadius: this server's geometry backend has no radius search");
}

SuggestResult GeometryBackend::suggest_radius(const PolygonSet&, const SuggestOptions&, EngineKind,
                                              const CancelHook&, const DeconstructLimits&) {
  throw NotAvailable("SuggestRadius: this server's geometry backend has no radius suggestion");
}

} // namespace penshape::daemon
