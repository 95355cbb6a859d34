// Whether a stroke is a stretch of a round shape drawn in pieces (round_pieces.hpp).
#include "recognize/group/round_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "recognize/classify/tracing.hpp"
#include "recognize/fitting/geometry.hpp"
#include "recognize/fitting/path_turn.hpp"
#include "recognize/group/group_plausibility.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
namespace {

// The round `shape`'s own path over the stretch a piece spans: between the points nearest the
// piece's ends, the way round (of a closed shape) that holds the piece's middle. How far it
// stands out from its chord, and its length.
struct ShapeSpan {
  double sagitta = 0.0;
  double length = 0.0;
  PointD middle; // the path's point halfway along the stretch
};
ShapeSpan span_of(const std::vector<PointD>& clean, const std::vector<PointD>& piece) {
  const ArcLengthPath path(clean);
  const double total = path.length();
  const bool closed = closed_path(clean);
  const ArcLengthPath along(piece);
  double from = path.nearest(piece.front()).at;
  double to = path.nearest(piece.back()).at;
  const double middle = path.nearest(along.point_at(0.5 * along.length())).at;
  if (from > to) std::swap(from, to);
  if (closed && (middle < from || middle > to)) { // the other way round, through the start
    std::swap(from, to);
    to += total;
  }
  const auto at = [&](double t) { return path.point_at(t >= total ? t - total : t); };
  const PointD a = at(from);
  const PointD b = at(to);
  ShapeSpan out{0.0, to - from, at(0.5 * (from + to))};
  constexpr int kSteps = 16;
  for (int k = 1; k < kSteps; ++k) {
    const PointD p = at(from + (to - from) * static_cast<double>(k) / kSteps);
    out.sagitta = std::max(out.sagitta, segment_distance(p, a, b));
  }
  return out;
}

// Whether the piece bends the way the shape's own path over it (`span`) does, standing out from
// its chord on the same side by at least kMinBendShare of that path's sagitta: a hand's stretch of
// the shape, however it wobbles into corners or hooks at its ends. A D's stem or a null sign's
// bar is straight where the shape bends.
bool bends_with(const ShapeSpan& span, const std::vector<PointD>& piece) {
  const PointD a = piece.front();
  const PointD chord = piece.back() - a;
  const double length = std::sqrt(dot(chord, chord));
  if (!(length > 0)) return false;
  const double side = cross(chord, span.middle - a) >= 0 ? 1.0 : -1.0;
  double bulge = 0.0;
  for (const PointD& p : piece) bulge = std::max(bulge, side * cross(chord, p - a) / length);
  return bulge >= kMinBendShare * span.sagitta;
}

// The way a path leaves its start (`front`) or its end, outwards: from its point `reach` along
// it (at most half of it) to that end.
PointD leaving(const std::vector<PointD>& path, bool front, double reach) {
  const ArcLengthPath along(path);
  const double r = std::min(reach, 0.5 * along.length());
  return front ? path.front() - along.point_at(r)
               : path.back() - along.point_at(along.length() - r);
}

// Whether piece `i` of `paths` meets the others at corners wherever it meets one: at each end
// of it that another piece's end lies within `join` of, the nearest such piece goes on turned by
// more than kMaxSmoothJoinTurn from the way the piece arrives (each way taken over epsilon of its
// path). A D's stem meets its bowl at two corners, a note's stem its head at one; a circle's
// piece goes on as the curve does, bar a hook where the hand started or stopped.
bool meets_at_corners(const std::vector<std::vector<PointD>>& paths, std::size_t i, double join,
                      double epsilon) {
  bool met = false;
  for (const bool front : {true, false}) {
    const PointD end = front ? paths[i].front() : paths[i].back();
    double nearest = join;
    std::optional<PointD> goes_on;
    for (std::size_t j = 0; j < paths.size(); ++j) {
      if (j == i || paths[j].size() < 2) continue;
      for (const bool other_front : {true, false}) {
        const PointD e = other_front ? paths[j].front() : paths[j].back();
        if (distance(e, end) > nearest) continue;
        nearest = distance(e, end);
        goes_on = -1.0 * leaving(paths[j], other_front, epsilon);
      }
    }
    if (!goes_on) continue;
    met = true;
    if (angle_between(leaving(paths[i], front, epsilon), *goes_on) <= kMaxSmoothJoinTurn)
      return false;
  }
  return met;
}

} // namespace

bool follows_round_shape(const Recognition& shape, const std::vector<std::vector<PointD>>& paths,
                         std::size_t i, double join) {
  const std::vector<PointD>& piece = paths[i];
  if (shape.clean.size() < 2 || piece.size() < 2) return false;
  const double flat = kArcMinSagitta * shape.epsilon;
  const ShapeSpan span = span_of(shape.clean, piece);
  if (distance(piece.front(), piece.back()) > span.length + flat) return false;
  const GroupRules& rules = group_rules();
  const bool along = span.sagitta < flat ? rules.flat_round_pieces
                                         : rules.bent_round_pieces && bends_with(span, piece);
  return along && !meets_at_corners(paths, i, join, shape.epsilon);
}

} // namespace penshape::recognize_detail
