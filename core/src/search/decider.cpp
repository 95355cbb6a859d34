// The default Decider: penshape::deconstruct() on a fixed polygon.
#include "penshape/core/search.hpp"

namespace penshape {

Decider make_decider(const PolygonSet& q, EngineKind engine, const CancelHook& cancel,
                     const DeconstructLimits& limits) {
  return [q, engine, cancel, limits](const Rational& r, const Rational& eps, const Rational& d) {
    return deconstruct(q, {r, eps, d, engine}, cancel, limits);
  };
}

} // namespace penshape
