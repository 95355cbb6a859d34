#pragma once
// Conversions between penshape.v1 messages and core types, with the validation of everything a
// client sends. Errors are FieldError whose message names the field by its path in the request,
// e.g. "polygon.polygons[0].outer.points[3].x is NaN"; the services answer INVALID_ARGUMENT.
#include <stdexcept>
#include <string>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_set.hpp"
#include "penshape/daemon/limits.hpp"
#include "penshape/daemon/pen_settings.hpp"
#include "penshape/proto/pen_types.hpp"
#include "penshape/types/stroke.hpp"
#include "penshape/v1/geometry.pb.h"
#include "penshape/v1/types.pb.h"

namespace penshape::daemon {

struct FieldError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// --- client → server (validating) -------------------------------------------------------------

// A polygon set: at least one polygon, rings of >= 3 points, finite coordinates within
// limits.max_abs_coordinate, exact_points (when given) as many as points and well-formed, at most
// limits.max_vertices vertices in all. Exact points win over display points when both are given.
// Geometric validity (simple rings, holes inside) is checked by the core (InvalidInput).
PolygonSet polygon_set_from_proto(const v1::PolygonSet& message, const std::string& field,
                                  const Limits& limits);

// A Scalar that must be present; doubles convert exactly, rationals are "p/q" or "p".
Rational scalar_from_proto(const v1::Scalar& message, bool present, const std::string& field,
                           const Limits& limits);

// "p/q" or "p" (optional '-', decimal digits, q > 0), canonicalised.
Rational parse_rational(const std::string& text, const std::string& field, const Limits& limits);

// r > 0, eps > 0, 0 < delta < eps, delta >= r / limits.min_precision_denominator; delta defaults
// to eps / 8 when absent.
DeconstructParams deconstruct_params_from_proto(const v1::DeconstructRequest& request,
                                                const Limits& limits);

// A stroke: at most limits.max_stroke_samples samples in non-decreasing time, coordinates within
// the tablet's maxima when those are set, resolutions finite and >= 0 (> 0 when
// `needs_resolution`).
Stroke stroke_from_proto(const v1::Stroke& message, const std::string& field, const Limits& limits,
                         bool needs_resolution);
TabletInfo tablet_from_proto(const v1::TabletInfo& message, const std::string& field,
                             bool needs_resolution);
PenSample sample_from_proto(const v1::PenSample& message); // proto::from_proto, tilt rule there

// The fields present; values validated (ranges in pen_settings.hpp).
PenSettingsUpdate settings_update_from_proto(const v1::PenSettings& message,
                                             const std::string& field);

// --- server → client ----------------------------------------------------------------------------

void to_proto(const PolygonSet& set, v1::PolygonSet* out); // exact and display coordinates
void to_proto(const Rational& value, v1::ExactScalar* out);
using proto::to_proto; // PenSample, TabletInfo, Stroke: the proto library's one conversion
void to_proto(const PenSettings& settings, v1::PenSettings* out);
v1::Answer to_proto(Answer answer);
v1::Engine to_proto(EngineKind engine);
EngineKind engine_from_proto(v1::Engine engine, const std::string& field);
// Answer, resolved parameters, solution and certificate of a deconstruction.
void to_proto(const DeconstructResult& result, v1::DeconstructResponse* out);

} // namespace penshape::daemon
