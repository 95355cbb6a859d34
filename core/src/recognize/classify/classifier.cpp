// recognize(): tolerance rule, family fits, certification and the choice of the winner.
#include "recognize/classify/classifier.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <optional>

#include "geometry/exact_predicates.hpp"
#include "recognize/certify/certificate.hpp"
#include "recognize/certify/ink_certificate.hpp"
#include "recognize/classify/annulus_polish.hpp"
#include "recognize/classify/corner_sharpness.hpp"
#include "recognize/classify/sharp_polygon.hpp"
#include "recognize/classify/tracing.hpp"
#include "recognize/fitting/dot.hpp"
#include "recognize/fitting/skeleton_seeds.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
namespace {

// Whether two non-adjacent segments of the path cross (a closed path's first and last segments
// are adjacent too).
bool self_crossing(const std::vector<PointD>& path) {
  const bool closed = path.size() > 3 && path.front() == path.back();
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    for (std::size_t j = i + 2; j + 1 < path.size(); ++j) {
      if (closed && i == 0 && j + 2 == path.size()) continue;
      if (detail::segments_cross_properly(path[i], path[i + 1], path[j], path[j + 1])) return true;
    }
  }
  return false;
}

// Net over total turning of the stroke, measured on a coarse resampling (pen jitter averages out).
double turning_monotonicity(const PreparedStroke& s) {
  const std::vector<PointD> q = resample(s.points, 16);
  double net = 0, total = 0;
  for (std::size_t i = 1; i + 1 < q.size(); ++i) {
    const PointD u = q[i] - q[i - 1];
    const PointD v = q[i + 1] - q[i];
    const double a = std::atan2(cross(u, v), dot(u, v));
    net += a;
    total += std::abs(a);
  }
  return total > 0 ? std::abs(net) / total : 1.0;
}

// Total absolute turning of the stroke on a coarse resampling (radians), counting only the
// turns that matter at the tolerance's scale: a vertex within epsilon / 4 of its neighbours'
// chord is pen jitter, not a turn.
double stroke_turning(const PreparedStroke& s, double epsilon) {
  const std::vector<PointD> q = resample(s.points, 16);
  double total = 0;
  for (std::size_t i = 1; i + 1 < q.size(); ++i) {
    if (segment_distance(q[i], q[i - 1], q[i + 1]) < 0.25 * epsilon) continue;
    const PointD u = q[i] - q[i - 1];
    const PointD v = q[i + 1] - q[i];
    total += std::abs(std::atan2(cross(u, v), dot(u, v)));
  }
  return total;
}

// The largest turn at a corner of a closed polygon (radians).
double sharpest_turn(const std::vector<PointD>& v) {
  double out = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const PointD u = v[i] - v[(i + v.size() - 1) % v.size()];
    const PointD w = v[(i + 1) % v.size()] - v[i];
    out = std::max(out, std::abs(std::atan2(cross(u, w), dot(u, w))));
  }
  return out;
}

// Total absolute turning of the clean shape (radians).
double shape_turning(const Fit& f) {
  if (f.clean.kind != CleanShape::Kind::kPolyline) return std::abs(f.clean.sweep);
  std::vector<PointD> p = f.clean.path;
  const bool closed = p.size() > 2 && p.front() == p.back();
  if (closed) p.push_back(p[1]); // the turn at the first vertex
  double total = 0;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const PointD u = p[i] - p[i - 1];
    const PointD v = p[i + 1] - p[i];
    total += std::abs(std::atan2(cross(u, v), dot(u, v)));
  }
  return total;
}

// The hand's evidence against any snap: traced over, wiggling, or a straight open shape drawn
// too loosely.
std::string drawing_implausibility(const PreparedStroke& s, const Fit& f, const Certificate& c,
                                   const RecognizerConfig& config) {
  const double clean_length = path_length(f.clean.sample(s.size / 64.0));
  // Measured on the fit points (48 along the stroke) so that sample jitter does not count.
  if (path_length(s.fit_points) > kMaxTracing * clean_length) {
    return "the stroke is much longer than the shape (traced over, a scribble or writing)";
  }
  if (stroke_turning(s, c.epsilon) > shape_turning(f) + kMaxExtraTurning) {
    return "the stroke turns far more than the shape (wiggles: writing or a scribble)";
  }
  const bool straight_open = f.shape == ShapeClass::kSegment || f.shape == ShapeClass::kPolyline;
  // Precision is a property of the drawing: read it on the bound of the (thinned) path the
  // fit was checked on, without the thinning's tau (which says nothing about the hand).
  if (straight_open && c.bound - s.thinning > config.straight_fraction * c.epsilon) {
    return "a straight open shape must fit within straight_fraction * epsilon";
  }
  return {};
}

std::string polyline_implausibility(const Fit& f, const Certificate& c) {
  const std::vector<PointD>& v = f.params.vertices;
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    if (segment_distance(v[i], v[i - 1], v[i + 1]) < 0.5 * c.epsilon) {
      return "a polyline corner is within epsilon / 2 of its neighbours' chord (not a corner)";
    }
  }
  if (self_crossing(f.clean.path))
    return "the open polyline crosses itself (a gesture, not a shape)";
  return {};
}

std::string polygon_implausibility(const PreparedStroke& s, const Fit& f, const Certificate& c) {
  if (self_crossing(f.clean.path)) {
    return "the polygon crosses itself (a star or a scribble, not a polygon)";
  }
  if (c.bound - s.thinning > kPolygonFraction * c.epsilon) {
    return "a polygon of 5..8 corners must fit within 0.85 epsilon (drawn as straight sides)";
  }
  if (sharpest_turn(f.params.vertices) > kMaxPolygonTurn) {
    return "a polygon corner turns back by more than 150 degrees (a line drawn down and back)";
  }
  return {};
}

// A diamond is a rhombus whose angles are far from 90 degrees: its acute angle, 2 atan(b / a)
// for half-diagonals b <= a, is below a right angle by more than kDiamondSkew. Closer, it is a
// square (standing on a corner, or a box drawn skewed).
std::string diamond_implausibility(const Fit& f, double skew) {
  const double a = std::max(f.params.radius_x, f.params.radius_y);
  const double b = std::min(f.params.radius_x, f.params.radius_y);
  if (std::numbers::pi / 2 - 2.0 * std::atan2(b, a) <= skew) {
    return "the rhombus's angles are within 15 degrees of right angles (a square or a skewed box)";
  }
  return {};
}

// A closed polygon's corners must be corners: sides of at least epsilon, corners off their
// neighbours' chord by at least epsilon (epsilon / 2, as a polyline's, where the stroke turns
// sharply there: an octagon's corners stand out less than epsilon at the default tolerance; down
// to epsilon / 4 at a corner the stroke turns at by kMinFlatCornerTurn of a regular polygon's
// turn: a hand's wobble flattens one corner of an octagon, not the turn it made there).
std::string corner_implausibility(const PreparedStroke& s, const Fit& f, const Certificate& c,
                                  bool sharp, double min_flat_corner_turn) {
  const double off_chord = (sharp ? kSharpCornerOffChord : 1.0) * c.epsilon;
  const std::vector<PointD>& v = f.params.vertices;
  std::optional<ArcLengthPath> path; // made on first use: most corners stand out enough
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (distance(v[i], v[(i + 1) % v.size()]) < c.epsilon) {
      return "a side is shorter than epsilon (a corner drawn round, not a side)";
    }
    const PointD prev = v[(i + v.size() - 1) % v.size()];
    const double off = segment_distance(v[i], prev, v[(i + 1) % v.size()]);
    if (off >= off_chord) continue;
    if (sharp && off >= kTurnedCornerOffChord * c.epsilon) {
      if (!path) path.emplace(s.points);
      const std::optional<double> turn = stroke_turn_at_corner(*path, v, i, kCornerWindow);
      if (turn && *turn >= min_flat_corner_turn * regular_turn(v.size())) continue;
    }
    return "a corner is too near its neighbours' chord (not a corner)";
  }
  return {};
}

// A triangle's, a quadrilateral's or a polygon's corners are fitted where the hand turned: a
// stroke that passes them as a curve does (a heart's lobes, a loop on a stick, a star whose
// points a pentagon cuts off) only lies in their band (kMinFittedCornerShare). The corners of
// model shapes (rectangle, square, diamond) may be drawn round, one by one, but a stroke that
// passes all of them as a circle does is a round shape in their band (kMinModelCornerShare).
std::string fitted_corner_implausibility(const PreparedStroke& s, const Fit& f,
                                         const RuleThresholds& rules) {
  const bool fitted = f.shape == ShapeClass::kTriangle || f.shape == ShapeClass::kQuadrilateral ||
                      f.shape == ShapeClass::kPolygon || f.shape == ShapeClass::kRegularPolygon;
  const bool model = f.shape == ShapeClass::kRectangle || f.shape == ShapeClass::kSquare ||
                     f.shape == ShapeClass::kDiamond;
  // No measured corner is no evidence either way.
  if (fitted) {
    const std::optional<double> least =
        measured_corner_share(s.points, f.params.vertices, kCornerWindow);
    if (least && *least < rules.min_fitted_corner_share) {
      return "the stroke passes a corner as a curve does (it turns there by less than half the "
             "corner's turn: a heart's lobe, a loop)";
    }
  }
  if (model) {
    const std::optional<double> mean =
        mean_corner_share(s.points, f.params.vertices, kCornerWindow);
    if (mean && *mean < rules.min_model_corner_share) {
      return "the stroke passes the corners as a circle does (on the whole it turns there by less "
             "than the model corners' share: a round shape drawn squarish)";
    }
  }
  return {};
}

// A shape is traced once, one way round: a stroke that runs back over a share of the shape's path
// (a stem drawn down and up, a question mark's hook) only stays in the shape's band.
std::string tracing_implausibility(const PreparedStroke& s, const Fit& f, double max_backtrack) {
  const std::vector<PointD> path =
      f.clean.kind == CleanShape::Kind::kPolyline ? f.clean.path : f.clean.sample(s.size / 64.0);
  // An open shape's strokes chain end to end one way (a line drawn twice runs back); a closed
  // one's may overlap where they close it, and each is then taken as drawn.
  const bool as_drawn = !s.piece_fit_points.empty() && closed_path(path);
  const double back =
      as_drawn ? backtrack_share(s.piece_fit_points, path) : backtrack_share(s.fit_points, path);
  if (back > max_backtrack) {
    return "the stroke runs back along the shape (a stem drawn twice: a letter or a note)";
  }
  return {};
}

// Why a certified candidate is not a plausible snap (empty when it is); rules in recognize.hpp.
std::string implausibility(const PreparedStroke& s, const Fit& f, const Certificate& c,
                           const RecognizerConfig& config, const RuleThresholds& rules) {
  if (std::string why = drawing_implausibility(s, f, c, config); !why.empty()) return why;
  if (std::string why = tracing_implausibility(s, f, rules.max_backtrack); !why.empty()) {
    return why;
  }
  if (f.shape == ShapeClass::kPolyline) return polyline_implausibility(f, c);
  if (f.shape == ShapeClass::kPolygon) {
    if (std::string why = polygon_implausibility(s, f, c); !why.empty()) return why;
  }
  if (f.shape == ShapeClass::kPolygon || f.shape == ShapeClass::kRegularPolygon) {
    if (std::string why = extra_corner_implausibility(s, f); !why.empty()) return why;
  }
  if (f.shape == ShapeClass::kDiamond) {
    if (std::string why = diamond_implausibility(f, rules.diamond_skew); !why.empty()) return why;
  }
  if (std::string why = fitted_corner_implausibility(s, f, rules); !why.empty()) return why;
  const bool sharp = sharp_polygon(s, f, rules);
  if (has_corners(f.shape))
    return corner_implausibility(s, f, c, sharp, rules.min_flat_corner_turn);
  if (f.shape == ShapeClass::kRegularPolygon && !sharp) {
    const double n = static_cast<double>(f.params.vertices.size());
    if (f.params.radius_x * (1.0 - std::cos(std::numbers::pi / n)) < 0.5 * c.epsilon) {
      return "the regular polygon's corners stand out from its circle by less than epsilon / 2 "
             "and the stroke rounds them";
    }
  }
  if (f.shape == ShapeClass::kArc && turning_monotonicity(s) < config.arc_monotone_turning) {
    return "the stroke turns both ways (not an arc)";
  }
  if (f.shape == ShapeClass::kArc &&
      f.params.radius_x * (1.0 - std::cos(f.params.sweep_angle / 2)) < kArcMinSagitta * c.epsilon) {
    return "the arc stands out from its chord by less than epsilon / 2 (a line drawn bowed)";
  }
  return {};
}

std::vector<PointD> display_path(const CleanShape& c, double size) {
  if (c.kind == CleanShape::Kind::kPolyline) return c.path;
  return c.sample(size / 40.0);
}

} // namespace

bool has_corners(ShapeClass shape) {
  return shape == ShapeClass::kTriangle || shape == ShapeClass::kQuadrilateral ||
         shape == ShapeClass::kRectangle || shape == ShapeClass::kSquare ||
         shape == ShapeClass::kDiamond || shape == ShapeClass::kPolygon;
}

// How tightly a candidate fits the stroke: the fit term of its rank.
double fit_measure(const Candidate& c) { return c.certificate.bound + kRmsWeight * c.rms; }

double degrees_of_freedom(const Fit& fit) {
  switch (fit.shape) {
    case ShapeClass::kSegment:
      return 4;
    case ShapeClass::kPolyline:
    case ShapeClass::kPolygon:
      return 2.0 * static_cast<double>(fit.params.vertices.size());
    case ShapeClass::kTriangle:
      return 6;
    case ShapeClass::kQuadrilateral:
      return 8;
    case ShapeClass::kRectangle:
      return 5;
    case ShapeClass::kSquare:
      return 4;
    case ShapeClass::kDiamond:
      return 5; // centre, angle, two half-diagonals
    case ShapeClass::kRegularPolygon:
      return 6;
    case ShapeClass::kCircle:
      return 3;
    case ShapeClass::kEllipse: // centre, two axes, angle
    case ShapeClass::kArc:     // centre, radius, two end angles
      return 5;
    case ShapeClass::kArrow:
    case ShapeClass::kDoubleArrow: {
      // A curved shaft: one more; each bend of a bent shaft: two more; a shaft's end short of
      // the tip: two more.
      const double base = fit.shape == ShapeClass::kArrow ? 8 : 12;
      return base + (fit.params.shaft_bulge == 0.0 ? 0 : 1) +
             2.0 * static_cast<double>(fit.params.shaft_bends.size()) +
             (fit.params.shaft_end ? kGapParameters : 0.0);
    }
    case ShapeClass::kFreeform:
    case ShapeClass::kDot: // never fitted (dot.hpp)
      break;
  }
  return 0;
}

bool is_closed(const PreparedStroke& s, double epsilon) {
  const std::size_t n = s.fit_points.size();
  const std::size_t fifth = n / 5 + 1;
  const std::span<const PointD> pts(s.fit_points);
  const double limit = kClosureEpsilons * epsilon;
  return polyline_distance(pts.back(), pts.first(fifth)) <= limit ||
         polyline_distance(pts.front(), pts.last(fifth)) <= limit;
}

std::vector<Family> all_families(const RecognizerConfig& config) {
  std::vector<Family> out{{ShapeClass::kSegment, 0},        {ShapeClass::kArc, 0},
                          {ShapeClass::kTriangle, 0},       {ShapeClass::kQuadrilateral, 0},
                          {ShapeClass::kRectangle, 0},      {ShapeClass::kSquare, 0},
                          {ShapeClass::kDiamond, 0},        {ShapeClass::kCircle, 0},
                          {ShapeClass::kEllipse, 0},        {ShapeClass::kRegularPolygon, 5},
                          {ShapeClass::kRegularPolygon, 6}, {ShapeClass::kRegularPolygon, 8}};
  for (std::size_t k = 2; k <= config.max_polyline_segments; ++k) {
    out.push_back({ShapeClass::kPolyline, k + 1});
  }
  for (std::size_t k = kMinPolygonCorners; k <= kMaxPolygonCorners; ++k) {
    out.push_back({ShapeClass::kPolygon, k});
  }
  return out;
}

double minimum_rank(const Family& family) {
  Fit f;
  f.shape = family.shape;
  f.params.vertices.resize(family.vertices);
  return kPricePerParameter * degrees_of_freedom(f);
}

bool wins_on_corners(const Family& family) {
  return family.shape == ShapeClass::kPolygon || family.shape == ShapeClass::kRegularPolygon;
}

Family family_of(const Fit& f) {
  if (f.shape == ShapeClass::kPolyline || f.shape == ShapeClass::kRegularPolygon ||
      f.shape == ShapeClass::kPolygon) {
    return {f.shape, f.params.vertices.size()};
  }
  return {f.shape, 0};
}

std::vector<Fit> fit_all(const PreparedStroke& s, const RecognizerConfig& config, double epsilon,
                         const std::vector<Family>& skip) {
  auto wanted = [&skip](ShapeClass c, std::size_t n = 0) {
    return std::find(skip.begin(), skip.end(), Family{c, n}) == skip.end();
  };
  std::vector<Fit> fits;
  auto add = [&fits](std::optional<Fit> f) {
    if (f && std::isfinite(f->fit_error)) fits.push_back(std::move(*f));
  };
  if (!is_closed(s, epsilon)) {
    if (wanted(ShapeClass::kSegment)) add(fit_segment(s));
    for (std::size_t k = 2; k <= config.max_polyline_segments; ++k) {
      if (wanted(ShapeClass::kPolyline, k + 1)) add(fit_polyline(s, k));
    }
    if (wanted(ShapeClass::kArc)) add(fit_arc(s));
    return fits;
  }
  if (wanted(ShapeClass::kTriangle)) add(fit_polygon(s, 3));
  const bool rectangles =
      wanted(ShapeClass::kRectangle) || wanted(ShapeClass::kSquare) || wanted(ShapeClass::kDiamond);
  if (rectangles || wanted(ShapeClass::kQuadrilateral)) {
    std::optional<Fit> quad = fit_polygon(s, 4);
    if (quad) {
      if (rectangles) {
        for (Fit& f : fit_rectangles(s, *quad)) {
          if (wanted(f.shape)) add(std::move(f));
        }
      }
      if (wanted(ShapeClass::kQuadrilateral)) add(std::move(quad));
    }
  }
  for (std::size_t k = kMinPolygonCorners; k <= kMaxPolygonCorners; ++k) {
    if (wanted(ShapeClass::kPolygon, k)) {
      std::vector<Fit> more = polygon_fits(s, k);
      fits.insert(fits.end(), std::make_move_iterator(more.begin()),
                  std::make_move_iterator(more.end()));
    }
  }
  std::optional<Fit> circle = fit_circle(s);
  if (circle) {
    for (const std::size_t n : {std::size_t{5}, std::size_t{6}, std::size_t{8}}) {
      if (wanted(ShapeClass::kRegularPolygon, n)) {
        add(fit_regular_polygon(s, n, circle->params.center, circle->params.radius_x));
      }
    }
    if (wanted(ShapeClass::kCircle)) add(std::move(circle));
  }
  if (wanted(ShapeClass::kEllipse)) add(fit_ellipse(s));
  return fits;
}

std::vector<Scored> evaluate(const PreparedStroke& s, std::vector<Fit> fits, double epsilon,
                             double pen_radius, const RecognizerConfig& config,
                             const RuleThresholds& rules) {
  std::vector<Scored> out;
  for (Fit& f : fits) {
    Scored sc;
    Candidate& c = sc.candidate;
    c.shape = f.shape;
    c.params = f.params;
    if (f.fit_error <= kCertifyIfBelow * epsilon) {
      c.certificate = certify(s, f.clean, epsilon, pen_radius);
    } else {
      c.certificate.epsilon = epsilon;
      c.certificate.pen_radius = pen_radius;
      c.certificate.bound = f.fit_error; // not certified; the fit's estimate for ranking
    }
    if (c.certificate.certified) c.rejected = implausibility(s, f, c.certificate, config, rules);
    c.rms = rms_distance(s.fit_points, f.clean);
    c.clean = display_path(f.clean, s.size);
    sc.rank = fit_measure(c) / epsilon + kPricePerParameter * degrees_of_freedom(f);
    sc.snap = c.certificate.certified && c.rejected.empty();
    sc.fit = std::move(f);
    out.push_back(std::move(sc));
  }
  settle(s, out, rules);
  return out;
}

void settle(const PreparedStroke& s, std::vector<Scored>& scored, const RuleThresholds& rules) {
  yield_to_sharp_polygon(s, scored, rules);
  yield_to_more_corners(s, scored, rules);
  std::stable_sort(scored.begin(), scored.end(), [](const Scored& a, const Scored& b) {
    if (a.snap != b.snap) return a.snap;
    return a.rank < b.rank;
  });
}

void confirm_on_ink(const InkRegion& q, std::vector<Scored>& scored) {
  for (Scored& sc : scored) {
    if (!sc.snap) break; // sorted: the snaps come first
    const Certificate& path = sc.candidate.certificate;
    sc.candidate.certificate = certify_ink(q, sc.fit.clean, path.epsilon, path.pen_radius);
    sc.snap = sc.candidate.certificate.certified;
    if (sc.snap) break; // the winner; later snaps keep their path certificate (alternatives)
  }
  std::stable_sort(scored.begin(), scored.end(), [](const Scored& a, const Scored& b) {
    if (a.snap != b.snap) return a.snap;
    return a.rank < b.rank;
  });
}

Recognition choose(std::vector<Scored> scored, double epsilon, double pen_radius) {
  Recognition out;
  out.epsilon = epsilon;
  out.pen_radius = pen_radius;
  out.certificate.epsilon = epsilon;
  out.certificate.pen_radius = pen_radius;
  std::size_t first_alternative = 0;
  if (!scored.empty() && scored.front().snap) {
    Candidate& w = scored.front().candidate;
    out.shape = w.shape;
    out.params = w.params;
    out.clean = w.clean;
    out.certificate = w.certificate;
    out.rms = w.rms;
    out.confidence = std::clamp(1.0 - w.certificate.bound / (2.0 * epsilon), 0.0, 1.0);
    first_alternative = 1;
  }
  for (std::size_t i = first_alternative; i < scored.size(); ++i) {
    out.alternatives.push_back(std::move(scored[i].candidate));
  }
  return out;
}

ToleranceChoice tolerance_for_box(PointD lo, PointD hi, const RecognizerConfig& config) {
  ToleranceChoice t;
  t.size = std::hypot(hi.x - lo.x, hi.y - lo.y);
  t.pen_radius =
      config.pen_radius > 0 ? config.pen_radius : config.default_pen_radius_fraction * t.size;
  t.epsilon = config.tolerance > 0 ? config.tolerance
                                   : std::min(config.tolerance_size_fraction * t.size +
                                                  config.tolerance_pen_radii * t.pen_radius,
                                              config.max_tolerance_fraction * t.size);
  return t;
}

} // namespace penshape::recognize_detail

namespace penshape {

using recognize_detail::PreparedStroke;

ToleranceChoice choose_tolerance(const std::vector<StrokePoint>& samples,
                                 const RecognizerConfig& config) {
  if (samples.empty()) return {};
  PointD lo{samples[0].x, samples[0].y};
  PointD hi = lo;
  for (const StrokePoint& s : samples) {
    lo = {std::min(lo.x, s.x), std::min(lo.y, s.y)};
    hi = {std::max(hi.x, s.x), std::max(hi.y, s.y)};
  }
  return recognize_detail::tolerance_for_box(lo, hi, config);
}

Recognition recognize(const std::vector<StrokePoint>& samples, const RecognizerConfig& config) {
  StrokeInput input;
  input.samples = samples;
  return recognize(input, config);
}

Recognition recognize(const StrokeInput& stroke, const RecognizerConfig& config_in) {
  RecognizerConfig config = config_in;
  if (stroke.pen_radius > 0) config.pen_radius = stroke.pen_radius;
  recognize_detail::validate_samples(stroke.samples, config);
  // A given ink is checked at once; one still being built only once a certificate reads it.
  if (stroke.ink != nullptr) (void)recognize_detail::given_ink(stroke);
  const ToleranceChoice tol = choose_tolerance(stroke.samples, config);
  if (recognize_detail::is_dot(stroke.samples)) {
    return recognize_detail::dot_recognition(stroke.samples, tol);
  }
  const PreparedStroke s = recognize_detail::prepare(
      stroke.samples, recognize_detail::thinning_tolerance(config, tol.epsilon));
  std::vector<recognize_detail::Fit> fits = recognize_detail::fit_all(s, config, tol.epsilon);
  if (stroke.skeleton && !stroke.skeleton->empty() && recognize_detail::is_closed(s, tol.epsilon)) {
    recognize_detail::apply_skeleton_seeds(s, *stroke.skeleton, fits);
  }
  std::vector<recognize_detail::Scored> scored =
      recognize_detail::evaluate(s, std::move(fits), tol.epsilon, tol.pen_radius, config);
  if (!scored.empty() && scored.front().snap) {
    recognize_detail::polish_with_annulus(s, scored.front(), config);
  }
  // Q is read only to confirm a snap: nothing else waits for an ink still being built.
  const bool snap = !scored.empty() && scored.front().snap;
  const InkPolygon* ink = snap ? recognize_detail::given_ink(stroke) : nullptr;
  if (ink != nullptr) {
    const recognize_detail::InkRegion q = recognize_detail::prepare_ink(*ink, tol.epsilon);
    recognize_detail::confirm_on_ink(q, scored);
  }
  Recognition out = recognize_detail::choose(std::move(scored), tol.epsilon, tol.pen_radius);
  if (stroke.ink != nullptr || stroke.ink_when_needed)
    out.certificate.method = "ink"; // freeform too: the ink decided (or screening)
  return out;
}

} // namespace penshape
