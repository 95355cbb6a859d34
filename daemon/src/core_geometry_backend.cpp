// The Geometry service's backend on the core library's engines. Compiled only when the engine is
// linked (PENSHAPE_DAEMON_WITH_ENGINE).
#include "penshape/core/arc_offset.hpp"
#include "penshape/daemon/geometry_backend.hpp"

namespace penshape::daemon {
namespace {

void to_proto(const PointD& p, v1::Point* out) {
  out->set_x(p.x);
  out->set_y(p.y);
}

void to_proto(const CurveRing& ring, v1::CurvedRing* out) {
  for (const BoundaryCurve& c : ring.curves) {
    v1::BoundaryPiece* piece = out->add_pieces();
    if (c.kind == BoundaryCurve::Kind::kSegment) {
      to_proto(c.start, piece->mutable_segment()->mutable_start());
      to_proto(c.end, piece->mutable_segment()->mutable_end());
    } else {
      v1::CircularArc* arc = piece->mutable_arc();
      to_proto(c.start, arc->mutable_start());
      to_proto(c.end, arc->mutable_end());
      to_proto(c.center, arc->mutable_center());
      arc->set_radius(c.radius);
      arc->set_counterclockwise(true); // offset_with_arcs: every arc runs counterclockwise
    }
  }
}

class CoreGeometryBackend final : public GeometryBackend {
 public:
  DeconstructResult deconstruct(const PolygonSet& q, const DeconstructParams& params,
                                const CancelHook& cancel,
                                const DeconstructLimits& limits) override {
    return penshape::deconstruct(q, params, cancel, limits);
  }

  SimplifyResult simplify(const PolygonSet& q, const DeconstructResult& raw,
                          const CancelHook& cancel, const DeconstructLimits& limits) override {
    return simplify_solution(q, raw, cancel, limits);
  }

  v1::CurvedRegion offset_boundary(const PolygonSet& p, const Rational& radius,
                                   const CancelHook& /*cancel*/) override {
    const CurvedRegion region = offset_with_arcs(p, to_double(radius));
    v1::CurvedRegion out;
    for (const CurvedPolygon& polygon : region.polygons) {
      v1::CurvedPolygon* q = out.add_polygons();
      to_proto(polygon.outer, q->mutable_outer());
      for (const CurveRing& hole : polygon.holes) to_proto(hole, q->add_holes());
    }
    out.set_max_error(region.max_error);
    return out;
  }

  ToleranceSearchResult search_tolerance(const PolygonSet& q, const Rational& radius,
                                         const Rational& width, EngineKind engine,
                                         const CancelHook& cancel, const DeconstructLimits& limits,
                                         const DecisionObserver& observe) override {
    return penshape::search_tolerance(observed(make_decider(q, engine, cancel, limits), observe),
                                      radius, width, fallback(q, engine, cancel, limits, observe));
  }

  RadiusSearchResult search_radius(const PolygonSet& q, const Rational& tolerance,
                                   const Rational& width,
                                   const std::optional<Rational>& upper_bound, EngineKind engine,
                                   const CancelHook& cancel, const DeconstructLimits& limits,
                                   const DecisionObserver& observe) override {
    RadiusSearchOptions options;
    options.precision = width;
    const Rational bound = upper_bound ? *upper_bound : enclosing_radius_bound(q) + tolerance;
    return penshape::search_radius(observed(make_decider(q, engine, cancel, limits), observe),
                                   tolerance, bound, options);
  }

  SuggestResult suggest_radius(const PolygonSet& q, const SuggestOptions& options,
                               EngineKind engine, const CancelHook& cancel,
                               const DeconstructLimits& limits) override {
    SuggestOptions with_fallback = options;
    with_fallback.fallback = fallback(q, engine, cancel, limits, {});
    return penshape::suggest_radius(make_decider(q, engine, cancel, limits), with_fallback);
  }

 private:
  static Decider observed(Decider decide, const DecisionObserver& observe) {
    if (!observe) return decide;
    return [decide = std::move(decide), &observe](const Rational& r, const Rational& eps,
                                                  const Rational& delta) {
      DeconstructResult result = decide(r, eps, delta);
      observe(result);
      return result;
    };
  }

  // The reference engine settles what the fast engine leaves UNDECIDED against its promise.
  static Decider fallback(const PolygonSet& q, EngineKind engine, const CancelHook& cancel,
                          const DeconstructLimits& limits, const DecisionObserver& observe) {
    if (engine != EngineKind::kFast) return {};
    return observed(make_decider(q, EngineKind::kReference, cancel, limits), observe);
  }
};

} // namespace

std::unique_ptr<GeometryBackend> make_core_geometry_backend() {
  return std::make_unique<CoreGeometryBackend>();
}

} // namespace penshape::daemon
