#include "penshape/daemon/proto_convert.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "penshape/types/lookup_table.hpp"

namespace penshape::daemon {
namespace {

std::string indexed(const std::string& field, const char* name, int index) {
  return field + "." + name + "[" + std::to_string(index) + "]";
}

std::string number_text(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// value.get_str(10) ("num" or "num/den"), formatted without GMP's digit conversion when both
// fit a machine word, as an ink polygon's grid coordinates do (its proto form has one per
// coordinate at every pen-up).
std::string rational_text(const Rational& value) {
  const mpz_srcptr num = value.get_num_mpz_t();
  const mpz_srcptr den = value.get_den_mpz_t();
  if (!mpz_fits_slong_p(num) || !mpz_fits_ulong_p(den)) return value.get_str(10);
  char text[48]; // a long (20 characters with its sign), '/', an unsigned long (20)
  char* end = std::to_chars(text, text + sizeof text, mpz_get_si(num)).ptr;
  if (mpz_cmp_ui(den, 1) != 0) {
    *end++ = '/';
    end = std::to_chars(end, text + sizeof text, mpz_get_ui(den)).ptr;
  }
  return {text, end};
}

Rational checked_coordinate(double v, const std::string& field, const Limits& limits) {
  if (std::isnan(v)) throw FieldError(field + " is NaN");
  if (std::isinf(v)) throw FieldError(field + " is infinite");
  if (std::fabs(v) > limits.max_abs_coordinate) {
    throw FieldError(field + " is " + number_text(v) + ", beyond the limit |coordinate| <= " +
                     number_text(limits.max_abs_coordinate));
  }
  return exact(v);
}

Ring ring_from_proto(const v1::Ring& ring, const std::string& field, const Limits& limits) {
  const int n = ring.points_size();
  const int m = ring.exact_points_size();
  if (m != 0 && n != 0 && m != n) {
    throw FieldError(field + ".exact_points has " + std::to_string(m) + " entries but points has " +
                     std::to_string(n));
  }
  const int count = m != 0 ? m : n;
  if (count < 3) {
    throw FieldError(field + " has " + std::to_string(count) + " points; a ring needs at least 3");
  }
  Ring out;
  out.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    if (m != 0) {
      const std::string at = indexed(field, "exact_points", i);
      const v1::ExactPoint& p = ring.exact_points(i);
      ExactPoint e{parse_rational(p.x(), at + ".x", limits),
                   parse_rational(p.y(), at + ".y", limits)};
      for (const Rational* c : {&e.x, &e.y}) {
        if (abs(*c) > exact(limits.max_abs_coordinate)) {
          throw FieldError(
              at + (c == &e.x ? ".x" : ".y") +
              " is beyond the limit |coordinate| <= " + number_text(limits.max_abs_coordinate));
        }
      }
      out.push_back(std::move(e));
    } else {
      const std::string at = indexed(field, "points", i);
      const v1::Point& p = ring.points(i);
      out.push_back({checked_coordinate(p.x(), at + ".x", limits),
                     checked_coordinate(p.y(), at + ".y", limits)});
    }
  }
  return out;
}

} // namespace

Rational parse_rational(const std::string& text, const std::string& field, const Limits& limits) {
  if (text.empty()) throw FieldError(field + " is empty; expected \"p/q\" or \"p\"");
  if (text.size() > limits.max_rational_chars) {
    throw FieldError(field + " has " + std::to_string(text.size()) +
                     " characters, beyond the limit " + std::to_string(limits.max_rational_chars));
  }
  std::size_t i = text[0] == '-' ? 1 : 0;
  const std::size_t numerator_start = i;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
  bool ok = i > numerator_start;
  bool zero_denominator = false;
  if (ok && i < text.size()) {
    ok = text[i] == '/';
    const std::size_t denominator_start = ++i;
    bool all_zero = true;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') all_zero &= text[i++] == '0';
    ok = ok && i > denominator_start && i == text.size();
    zero_denominator = ok && all_zero;
  }
  if (!ok) {
    throw FieldError(field + " is '" + text.substr(0, 64) +
                     "'; expected \"p/q\" or \"p\" (decimal integers, optional '-')");
  }
  if (zero_denominator) throw FieldError(field + " has a zero denominator");
  Rational value(text, 10);
  value.canonicalize();
  return value;
}

PolygonSet polygon_set_from_proto(const v1::PolygonSet& message, const std::string& field,
                                  const Limits& limits) {
  if (message.polygons_size() == 0) throw FieldError(field + ".polygons is empty");
  // Count first so an absurd request is refused before anything is converted.
  std::size_t vertices = 0;
  for (const auto& polygon : message.polygons()) {
    auto count = [](const v1::Ring& r) {
      return static_cast<std::size_t>(std::max(r.points_size(), r.exact_points_size()));
    };
    vertices += count(polygon.outer());
    for (const auto& hole : polygon.holes()) vertices += count(hole);
  }
  if (vertices > limits.max_vertices) {
    throw FieldError(field + " has " + std::to_string(vertices) + " vertices, beyond the limit " +
                     std::to_string(limits.max_vertices));
  }
  PolygonSet out;
  out.polygons.reserve(static_cast<std::size_t>(message.polygons_size()));
  for (int i = 0; i < message.polygons_size(); ++i) {
    const std::string at = indexed(field, "polygons", i);
    const v1::Polygon& polygon = message.polygons(i);
    if (!polygon.has_outer()) throw FieldError(at + ".outer is missing");
    PolygonWithHoles converted;
    converted.outer = ring_from_proto(polygon.outer(), at + ".outer", limits);
    for (int h = 0; h < polygon.holes_size(); ++h) {
      converted.holes.push_back(ring_from_proto(polygon.holes(h), indexed(at, "holes", h), limits));
    }
    out.polygons.push_back(std::move(converted));
  }
  return out;
}

Rational scalar_from_proto(const v1::Scalar& message, bool present, const std::string& field,
                           const Limits& limits) {
  switch (message.kind_case()) {
    case v1::Scalar::kValue: {
      const double v = message.value();
      if (std::isnan(v)) throw FieldError(field + ".value is NaN");
      if (std::isinf(v)) throw FieldError(field + ".value is infinite");
      return exact(v);
    }
    case v1::Scalar::kRational:
      return parse_rational(message.rational(), field + ".rational", limits);
    default:
      throw FieldError(field + (present ? " has neither value nor rational" : " is missing"));
  }
}

DeconstructParams deconstruct_params_from_proto(const v1::DeconstructRequest& request,
                                                const Limits& limits) {
  DeconstructParams params;
  params.radius = scalar_from_proto(request.radius(), request.has_radius(), "radius", limits);
  params.tolerance =
      scalar_from_proto(request.tolerance(), request.has_tolerance(), "tolerance", limits);
  if (sgn(params.radius) <= 0) throw FieldError("radius must be > 0");
  if (sgn(params.tolerance) <= 0) throw FieldError("tolerance must be > 0");
  if (request.has_precision()) {
    params.precision = scalar_from_proto(request.precision(), true, "precision", limits);
    if (sgn(params.precision) <= 0) throw FieldError("precision must be > 0");
    if (params.precision >= params.tolerance) {
      throw FieldError("precision must be < tolerance (delta < eps)");
    }
  } else {
    params.precision = params.tolerance / 8;
  }
  if (params.precision * limits.min_precision_denominator < params.radius) {
    throw FieldError("precision must be >= radius / " +
                     std::to_string(limits.min_precision_denominator) +
                     " (finer precisions need disk approximations beyond the engine's limit)");
  }
  params.engine = engine_from_proto(request.engine(), "engine");
  return params;
}

EngineKind engine_from_proto(v1::Engine engine, const std::string& field) {
  switch (engine) {
    case v1::ENGINE_UNSPECIFIED:
    case v1::ENGINE_FAST:
      return EngineKind::kFast;
    case v1::ENGINE_REFERENCE:
      return EngineKind::kReference;
    default:
      throw FieldError(field + " is " + std::to_string(static_cast<int>(engine)) +
                       ", not a known Engine");
  }
}

TabletInfo tablet_from_proto(const v1::TabletInfo& message, const std::string& field,
                             bool needs_resolution) {
  if (message.vendor_id() > 0xffff) throw FieldError(field + ".vendor_id is beyond 0xffff");
  if (message.product_id() > 0xffff) throw FieldError(field + ".product_id is beyond 0xffff");
  if (message.x_max() < 0) throw FieldError(field + ".x_max is negative");
  if (message.y_max() < 0) throw FieldError(field + ".y_max is negative");
  const std::pair<double, const char*> resolutions[] = {{message.x_resolution(), "x_resolution"},
                                                        {message.y_resolution(), "y_resolution"}};
  for (const auto& [value, name] : resolutions) {
    const std::string at = field + "." + name;
    if (std::isnan(value)) throw FieldError(at + " is NaN");
    if (!std::isfinite(value) || value < 0) throw FieldError(at + " must be finite and >= 0");
    if (needs_resolution && value == 0) {
      throw FieldError(at + " must be > 0 (device units per millimetre)");
    }
  }
  return proto::from_proto(message);
}

PenSample sample_from_proto(const v1::PenSample& message) { return proto::from_proto(message); }

Stroke stroke_from_proto(const v1::Stroke& message, const std::string& field, const Limits& limits,
                         bool needs_resolution) {
  Stroke stroke;
  stroke.id = message.id();
  stroke.tablet = tablet_from_proto(message.tablet(), field + ".tablet", needs_resolution);
  const int n = message.samples_size();
  if (n == 0) throw FieldError(field + ".samples is empty");
  if (static_cast<std::size_t>(n) > limits.max_stroke_samples) {
    throw FieldError(field + ".samples has " + std::to_string(n) + " samples, beyond the limit " +
                     std::to_string(limits.max_stroke_samples));
  }
  stroke.samples.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const v1::PenSample& m = message.samples(i);
    const std::string at = indexed(field, "samples", i);
    if (i > 0 && m.time_us() < message.samples(i - 1).time_us()) {
      throw FieldError(at + ".time_us goes back in time (" + std::to_string(m.time_us()) + " < " +
                       std::to_string(message.samples(i - 1).time_us()) + ")");
    }
    if (stroke.tablet.x_max > 0 && (m.x() < 0 || m.x() > stroke.tablet.x_max)) {
      throw FieldError(at + ".x is " + std::to_string(m.x()) + ", outside 0..tablet.x_max (" +
                       std::to_string(stroke.tablet.x_max) + ")");
    }
    if (stroke.tablet.y_max > 0 && (m.y() < 0 || m.y() > stroke.tablet.y_max)) {
      throw FieldError(at + ".y is " + std::to_string(m.y()) + ", outside 0..tablet.y_max (" +
                       std::to_string(stroke.tablet.y_max) + ")");
    }
    stroke.samples.push_back(sample_from_proto(m));
  }
  return stroke;
}

namespace {

// The snap triggers and their messages, read one way for requests and the other for answers.
constexpr LookupTable<SnapTrigger, v1::SnapTrigger, 3> kSnapTriggers{
    {{SnapTrigger::kPenUp, v1::SNAP_TRIGGER_PEN_UP},
     {SnapTrigger::kHold, v1::SNAP_TRIGGER_HOLD},
     {SnapTrigger::kBoth, v1::SNAP_TRIGGER_BOTH}}};

SnapTrigger snap_trigger_from_proto(const v1::PenSettings& message, const std::string& field) {
  if (const auto trigger = reverse_lookup(kSnapTriggers, message.snap_trigger())) return *trigger;
  throw FieldError((field.empty() ? "" : field + ".") + "snap_trigger is " +
                   std::to_string(static_cast<int>(message.snap_trigger())) +
                   "; expected SNAP_TRIGGER_PEN_UP, SNAP_TRIGGER_HOLD or SNAP_TRIGGER_BOTH");
}

v1::SnapTrigger to_proto(SnapTrigger trigger) {
  return lookup_or(kSnapTriggers, trigger, v1::SNAP_TRIGGER_BOTH);
}

} // namespace

PenSettingsUpdate settings_update_from_proto(const v1::PenSettings& message,
                                             const std::string& field) {
  PenSettingsUpdate update;
  if (message.has_pen_radius_mm()) update.pen_radius_mm = message.pen_radius_mm();
  if (message.has_tolerance_fraction()) update.tolerance_fraction = message.tolerance_fraction();
  if (message.has_precision_fraction()) update.precision_fraction = message.precision_fraction();
  if (message.has_snap_trigger()) update.snap_trigger = snap_trigger_from_proto(message, field);
  if (message.has_hold_ms()) update.hold_ms = message.hold_ms();
  if (message.has_hold_radius_mm()) update.hold_radius_mm = message.hold_radius_mm();
  if (message.has_snap_writing()) update.snap_writing = message.snap_writing();
  try {
    validate(update, field);
  } catch (const SettingsError& e) {
    throw FieldError(e.what());
  }
  return update;
}

void to_proto(const Rational& value, v1::ExactScalar* out) {
  out->set_rational(rational_text(value));
  out->set_approx(to_double(value));
}

void to_proto(const PolygonSet& set, v1::PolygonSet* out) {
  out->Clear();
  auto ring_to_proto = [](const Ring& ring, v1::Ring* r) {
    r->mutable_points()->Reserve(static_cast<int>(ring.size()));
    r->mutable_exact_points()->Reserve(static_cast<int>(ring.size()));
    for (const ExactPoint& p : ring) {
      const PointD d = to_double(p);
      auto* point = r->add_points();
      point->set_x(d.x);
      point->set_y(d.y);
      auto* e = r->add_exact_points();
      e->set_x(rational_text(p.x));
      e->set_y(rational_text(p.y));
    }
  };
  for (const PolygonWithHoles& polygon : set.polygons) {
    auto* p = out->add_polygons();
    ring_to_proto(polygon.outer, p->mutable_outer());
    for (const Ring& hole : polygon.holes) ring_to_proto(hole, p->add_holes());
  }
}

void to_proto(const PenSettings& settings, v1::PenSettings* out) {
  out->set_pen_radius_mm(settings.pen_radius_mm);
  out->set_tolerance_fraction(settings.tolerance_fraction);
  out->set_precision_fraction(settings.precision_fraction);
  out->set_snap_trigger(to_proto(settings.snap_trigger));
  out->set_hold_ms(static_cast<std::uint32_t>(settings.hold_ms));
  out->set_hold_radius_mm(settings.hold_radius_mm);
  out->set_snap_writing(settings.snap_writing);
}

v1::Answer to_proto(Answer answer) {
  static constexpr LookupTable<Answer, v1::Answer, 3> kAnswers{
      {{Answer::kYes, v1::ANSWER_YES},
       {Answer::kNo, v1::ANSWER_NO},
       {Answer::kUndecided, v1::ANSWER_UNDECIDED}}};
  return lookup_or(kAnswers, answer, v1::ANSWER_UNSPECIFIED);
}

v1::Engine to_proto(EngineKind engine) {
  return engine == EngineKind::kReference ? v1::ENGINE_REFERENCE : v1::ENGINE_FAST;
}

void to_proto(const DeconstructResult& result, v1::DeconstructResponse* out) {
  out->set_answer(to_proto(result.answer));
  v1::ResolvedParams* params = out->mutable_params();
  to_proto(result.params.radius, params->mutable_radius());
  to_proto(result.params.tolerance, params->mutable_tolerance());
  to_proto(result.params.precision, params->mutable_precision());
  params->set_engine(to_proto(result.engine));
  v1::DeconstructCertificate* certificate = out->mutable_certificate();
  certificate->set_disk_vertices(static_cast<std::uint32_t>(result.disk_vertices));
  switch (result.answer) {
    case Answer::kYes:
      to_proto(result.solution, out->mutable_solution());
      to_proto(result.hausdorff_bound, certificate->mutable_hausdorff_bound());
      certificate->set_statement(
          "P is inside inset(offset(Q, eps), r) and Q is inside offset(P, r + eps), so "
          "H(offset(P, r), Q) <= hausdorff_bound <= eps");
      break;
    case Answer::kNo:
      certificate->set_statement(
          "no polygonal P exists: the exterior disk approximation leaves part of Q uncovered");
      break;
    case Answer::kUndecided:
      certificate->set_statement("undecided at this precision; a smaller precision decides");
      break;
  }
}

} // namespace penshape::daemon
