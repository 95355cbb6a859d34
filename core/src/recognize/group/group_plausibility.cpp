// Drawn-in-pieces rules for unions of several strokes (group_plausibility.hpp).
#include "recognize/group/group_plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "geometry/exact_predicates.hpp"
#include "recognize/arrow/arrow_limits.hpp"
#include "recognize/classify/classifier.hpp"
#include "recognize/fitting/path_turn.hpp"
#include "recognize/fitting/thin_path.hpp"
#include "recognize/group/arrow_tip.hpp"
#include "recognize/group/group_classifier.hpp"
#include "recognize/group/round_pieces.hpp"
#include "recognize/group/stroke_chain.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
namespace {

bool is_round(ShapeClass c) {
  return c == ShapeClass::kCircle || c == ShapeClass::kEllipse || c == ShapeClass::kArc;
}

bool closed_round(ShapeClass c) { return c == ShapeClass::kCircle || c == ShapeClass::kEllipse; }

bool straight_sided_closed(ShapeClass c) { return convex_polygon(c) || c == ShapeClass::kPolygon; }

// Shapes whose corners follow a model (right angles, equal sides) rather than the drawn turns: a
// corner lies near the drawn one, not on it (rounds_corner). A triangle's, a quadrilateral's or a
// polygon's corners are fitted where the strokes turn.
bool model_corners(ShapeClass c) {
  return c == ShapeClass::kRectangle || c == ShapeClass::kSquare || c == ShapeClass::kDiamond ||
         c == ShapeClass::kRegularPolygon;
}

constexpr double kMinReachSine = 0.25; // a model corner's reach: at most 4 epsilon
constexpr int kReachSteps = 8;         // turns looked at on each side of the nearest point

// Whether a piece that is no arc alone lies in the band of an arc that stands out from its chord
// (kArcMinSagitta) and bends round the round `group`'s inside (its centre within
// kMaxBowedCentreOff of the group's radius from the group's centre): a bowed stroke, a hand-drawn
// third of a circle wobbling into corners (or hooked where the hand started or stopped) as often
// as not. A straight stroke is no such arc's: a D's stem, a null sign's bar.
bool bowed(const Recognition& own, const Recognition& group) {
  if (!group_rules().bowed_round_pieces) return false;
  const double radius = std::max(group.params.radius_x, group.params.radius_y);
  return std::any_of(own.alternatives.begin(), own.alternatives.end(), [&](const Candidate& c) {
    const double sagitta = c.params.radius_x * (1.0 - std::cos(0.5 * c.params.sweep_angle));
    return c.shape == ShapeClass::kArc && c.certificate.certified &&
           sagitta >= kArcMinSagitta * c.certificate.epsilon &&
           distance(c.params.center, group.params.center) <= kMaxBowedCentreOff * radius;
  });
}

// Why a piece recognized alone as `own` is no piece of a `group` (empty when it may be one).
std::string kind_mismatch(const Recognition& group, const Recognition& own) {
  if (is_round(group.shape) && !is_round(own.shape) && !bowed(own, group))
    return "a round shape has a piece that is no arc of it (a straight stroke, a D's stem)";
  // Not an arc: a side and a rounded corner drawn alone often read as one.
  if (!is_round(group.shape) && closed_round(own.shape)) {
    return "a straight-sided shape has a circle or ellipse among its pieces";
  }
  return {};
}

// Whether the piece passes a corner of the shape (v, between `before` and `after`) away from its
// ends without turning there (kMinCornerTurnShare): it rounds it as a curve does. A fitted corner
// lies where the stroke turns. A `model_corner` (model_corners) may lie as far as
// epsilon / sin(turn / 2) along its sides from the drawn one with the shape still within epsilon
// of it: the piece's sharpest turn within that reach of its nearest point counts (a curve turns as
// little there as anywhere on its bowl).
bool rounds_corner(const std::vector<PointD>& piece, PointD before, PointD v, PointD after,
                   double epsilon, bool model_corner) {
  const double shape_turn = angle_between(v - before, after - v);
  const double reach =
      model_corner ? epsilon / std::max(std::sin(0.5 * shape_turn), kMinReachSine) : 0.0;
  const ArcLengthPath path(piece);
  const ArcLengthPath::Nearest near = path.nearest(v);
  // Not on this piece, or where it starts or ends (a corner between two pieces).
  const double end = std::max(epsilon, reach);
  if (near.distance > epsilon || near.at < end || near.at > path.length() - end) return false;
  const int steps = model_corner ? kReachSteps : 0;
  std::optional<double> sharpest;
  for (int k = -steps; k <= steps; ++k) {
    const double at = near.at + (steps > 0 ? reach * static_cast<double>(k) / steps : 0.0);
    const std::optional<double> turn = path.turn_at(at, epsilon);
    if (turn && (!sharpest || *turn > *sharpest)) sharpest = turn;
  }
  return sharpest && *sharpest < group_rules().min_corner_turn_share * shape_turn;
}

// Whether some piece rounds a corner of the closed polygon `outline` (first vertex repeated;
// `model_corner` as for rounds_corner).
bool curve_for_corner(const std::vector<std::vector<PointD>>& paths,
                      const std::vector<PointD>& outline, double epsilon, bool model_corner) {
  const std::size_t n = outline.size() - 1;
  for (std::size_t k = 0; k < n; ++k) {
    const PointD before = outline[(k + n - 1) % n], v = outline[k], after = outline[(k + 1) % n];
    for (const std::vector<PointD>& p : paths) {
      if (rounds_corner(p, before, v, after, epsilon, model_corner)) return true;
    }
  }
  return false;
}

// Whether `a`, from the point x on its segment `i` to its nearer end, runs on along `b` farther
// than `join` and within `alongside` of it all the way: a closing stroke overlapping the first one
// (a shape drawn round once and a bit, cut), not a stroke leaving across it.
bool runs_on_along(const std::vector<PointD>& a, std::size_t i, PointD x,
                   const std::vector<PointD>& b, double join, double alongside) {
  std::vector<PointD> head(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(i) + 1);
  head.push_back(x);
  std::vector<PointD> tail{x};
  tail.insert(tail.end(), a.begin() + static_cast<std::ptrdiff_t>(i) + 1, a.end());
  const std::vector<PointD>& rest = path_length(head) < path_length(tail) ? head : tail;
  if (path_length(rest) <= join) return false;
  const ArcLengthPath along(b);
  return std::all_of(rest.begin(), rest.end(),
                     [&](PointD p) { return along.nearest(p).distance <= alongside; });
}

// Whether two pieces cross properly at a point farther than `join` from the ends of one of them
// (`in_both`: in the middle halves of both, kMiddleOfArrowPiece). Overshooting corners cross near
// the ends of both; an arrow's head crosses its shaft at the shaft's end (the tip, which the
// shaft may overshoot) and in the head's own middle. A crossing where one piece runs on along the
// other to its end (runs_on_along, within `alongside`) is an overlap, no crossing.
bool cross_in_middle(const std::vector<PointD>& a, const std::vector<PointD>& b, double join,
                     bool in_both, double alongside) {
  auto far_from_ends = [join, in_both](PointD x, const std::vector<PointD>& p) {
    const double margin = in_both ? std::max(join, kMiddleOfArrowPiece * path_length(p)) : join;
    return distance(x, p.front()) > margin && distance(x, p.back()) > margin;
  };
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    for (std::size_t j = 0; j + 1 < b.size(); ++j) {
      if (!detail::segments_cross_properly(a[i], a[i + 1], b[j], b[j + 1])) continue;
      PointD x;
      if (!line_intersection(a[i], a[i + 1] - a[i], b[j], b[j + 1] - b[j], x)) continue;
      const bool far_a = far_from_ends(x, a), far_b = far_from_ends(x, b);
      if (!(in_both ? far_a && far_b : far_a || far_b)) continue;
      if (!in_both && group_rules().overlaps_are_no_crossings &&
          (runs_on_along(a, i, x, b, join, alongside) ||
           runs_on_along(b, j, x, a, join, alongside)))
        continue;
      return true;
    }
  }
  return false;
}

// Whether two of the pieces cross in their middles (cross_in_middle).
bool pieces_cross(const std::vector<std::vector<PointD>>& paths, double stroke_epsilon, double join,
                  bool in_both) {
  std::vector<std::vector<PointD>> thin;
  thin.reserve(paths.size());
  for (const std::vector<PointD>& p : paths)
    thin.push_back(thin_path(p, kCrossingThinning * stroke_epsilon));
  for (std::size_t i = 0; i < thin.size(); ++i) {
    for (std::size_t j = i + 1; j < thin.size(); ++j) {
      if (cross_in_middle(thin[i], thin[j], join, in_both, kOverlapAlongside * stroke_epsilon))
        return true;
    }
  }
  return false;
}

// Why a stroke recognized alone is no piece of a `shape` (kind_mismatch; empty when none).
// `paths`: the strokes' distinct paths; `join`: how far apart chained ends may be.
std::string mismatched_piece(const Recognition& shape, std::span<const StrokeInput> strokes,
                             const std::vector<std::vector<PointD>>& paths, double join,
                             const RecognizerConfig& config) {
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    const StrokeInput& s = strokes[i];
    // A piece no larger than the shape's epsilon (a tick closing a circle's gap) is too small to
    // be told an arc or a side of it.
    if (choose_tolerance(s.samples, config).size <= shape.epsilon) continue;
    if (closed_round(shape.shape) && follows_round_shape(shape, paths, i, join)) continue;
    std::string why = kind_mismatch(shape, recognize(s.samples, config));
    if (!why.empty()) return why;
  }
  return {};
}

// Two strokes that start at one point and leave it each its own way: limbs from a junction (a
// stick figure's arms from its body, an X's strokes from a shared start), not one line drawn in
// two pieces, which goes on where the first piece stopped (or fills in towards it).
bool limbs_from_one_point(const std::vector<std::vector<PointD>>& paths, double join) {
  if (paths.size() != 2) return false;
  const std::vector<PointD>& a = paths[0];
  const std::vector<PointD>& b = paths[1];
  const bool chained =
      distance(a.back(), b.front()) <= join || distance(b.back(), a.front()) <= join;
  return !chained && distance(a.front(), b.front()) <= join;
}

// The rules of GroupRules for a union that chains end to end (empty when none refuses it).
std::string piece_rules(const Recognition& r, const std::vector<std::vector<PointD>>& paths,
                        double stroke_epsilon, double join) {
  const GroupRules& rules = group_rules();
  // The pieces of a written letter (A, H, X, I, an asterisk) and of a stick figure meet end to
  // end as an open polyline's do: nothing but the closing piece or a head tells a shape.
  if (rules.no_open_polylines && r.shape == ShapeClass::kPolyline) {
    return "an open polyline in pieces is no shape (letters meet end to end as well)";
  }
  if (rules.no_limbs_as_a_line && r.shape == ShapeClass::kSegment &&
      limbs_from_one_point(paths, join)) {
    return "two strokes leave one point each its own way (limbs from a junction, not a line)";
  }
  if (!straight_sided_closed(r.shape)) return {};
  if (rules.no_curved_sides && r.clean.size() >= 4 &&
      curve_for_corner(paths, r.clean, r.epsilon, model_corners(r.shape))) {
    return "a stroke passes a corner of the shape as a curve, without turning there (a D)";
  }
  if (rules.no_crossing_pieces && pieces_cross(paths, stroke_epsilon, join, false))
    return "two strokes of an outline cross away from their ends (a figure, no outline)";
  return {};
}

} // namespace

GroupRules& group_rules() {
  static GroupRules rules;
  return rules;
}

double apart_join(std::size_t strokes, double epsilon) {
  return strokes == 2 ? group_rules().apart_join * epsilon : 0.0;
}

bool kept_apart(const Recognition& r) { return r.shape == ShapeClass::kArrow; }

namespace {

// The largest epsilon of a stroke alone: a gap between pieces is measured against the pieces
// drawn, not against the whole group, whose epsilon grows with every piece added.
double stroke_epsilon_of(std::span<const StrokeInput> strokes, const RecognizerConfig& config) {
  double e = 0.0;
  for (const StrokeInput& s : strokes) e = std::max(e, choose_tolerance(s.samples, config).epsilon);
  return e;
}

// Why `r` is not kept as the group of `strokes` among the recent strokes `others`.
std::string why_not_kept(const Recognition& r, std::span<const StrokeInput> strokes,
                         std::span<const StrokeInput* const> others,
                         const RecognizerConfig& config) {
  std::string why = group_implausibility(r, strokes, config);
  if (!why.empty() || (r.shape != ShapeClass::kArrow && r.shape != ShapeClass::kDoubleArrow)) {
    return why;
  }
  std::vector<std::vector<PointD>> paths;
  paths.reserve(others.size());
  for (const StrokeInput* s : others) paths.push_back(distinct_path(s->samples));
  return tip_continued(r, paths, 2.0 * r.pen_radius + stroke_epsilon_of(strokes, config));
}

} // namespace

bool keep_union(UnionRecognition& u, std::span<const StrokeInput> strokes,
                std::span<const StrokeInput* const> others, const RecognizerConfig& config) {
  if (why_not_kept(u.recognition, strokes, others, config).empty()) return true;
  const ShapeClass winner = u.recognition.shape;
  const bool arrow_winner = winner == ShapeClass::kArrow || winner == ShapeClass::kDoubleArrow;
  auto kept = [&](std::optional<AlternativeReading> reading) {
    if (!reading || !why_not_kept(reading->recognition, strokes, others, config).empty()) {
      return false;
    }
    u.recognition = std::move(reading->recognition);
    u.rank = reading->rank;
    return true;
  };
  if (group_rules().arrow_when_refused && !arrow_winner && kept(read_as_arrow(u.recognition))) {
    return true;
  }
  // Straight pieces tell a straight-sided outline whose lumps a round band covers better.
  return group_rules().outline_when_round_refused && is_round(winner) &&
         kept(read_as(u.recognition, straight_sided_closed));
}

std::string group_implausibility(const Recognition& r, std::span<const StrokeInput> strokes,
                                 const RecognizerConfig& config) {
  if (strokes.size() < 2) return {};
  std::vector<std::vector<PointD>> paths;
  paths.reserve(strokes.size());
  for (const StrokeInput& s : strokes) paths.push_back(distinct_path(s.samples));
  const double stroke_epsilon = stroke_epsilon_of(strokes, config);
  const double join = 2.0 * r.pen_radius + stroke_epsilon;
  // An arrow's head meets its shaft at the head's middle (its tip), not at an end; no two of
  // its strokes cross in both their middles (the arms across a stick figure's body).
  if (r.shape == ShapeClass::kArrow || r.shape == ShapeClass::kDoubleArrow) {
    if (group_rules().no_crossing_pieces && pieces_cross(paths, stroke_epsilon, join, true))
      return "two strokes of an arrow cross in their middles (a figure, no arrow)";
    // A shaft and its barbs: a stroke more than the arrow has parts draws no part of it.
    const std::size_t parts = r.shape == ShapeClass::kArrow ? 3 : 5;
    if (group_rules().a_stroke_per_arrow_part && strokes.size() > parts)
      return "more strokes than the arrow has parts (a shaft and its barbs): a figure, no arrow";
    // Straight pieces or an arc: a loop alone (a note's head, a null sign's ring) is no part.
    return group_rules().no_round_arrow_pieces ? mismatched_piece(r, strokes, paths, join, config)
                                               : "";
  }
  for (const double jump : chain_jumps(paths)) {
    if (jump > join) {
      return "the strokes do not chain end to end (a jump between pieces is wider than 2 r + "
             "the epsilon of a piece)";
    }
  }
  if (std::string why = piece_rules(r, paths, stroke_epsilon, join); !why.empty()) return why;
  // Each piece is a piece of the shape's own kind: a D or a P (a bar and a bowl) is no ellipse,
  // a circle crossed by a bar no polygon, whatever band covers the union.
  return mismatched_piece(r, strokes, paths, join, config);
}

} // namespace penshape::recognize_detail
