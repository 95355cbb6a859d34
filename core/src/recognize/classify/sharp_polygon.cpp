// The sharp-polygon rule (see sharp_polygon.hpp).
#include "recognize/classify/sharp_polygon.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "recognize/classify/corner_sharpness.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {

double regular_turn(std::size_t k) { return 2.0 * std::numbers::pi / static_cast<double>(k); }

bool sharp_polygon(const PreparedStroke& s, const Fit& f, const RuleThresholds& rules) {
  return (f.shape == ShapeClass::kPolygon || f.shape == ShapeClass::kRegularPolygon) &&
         least_corner_share(s.points, f.params.vertices, kCornerWindow) >=
             rules.min_sharp_corner_share;
}

bool yields_to_sharp_polygon(const PreparedStroke& s, const Fit& f, const RuleThresholds& rules) {
  if (f.shape == ShapeClass::kCircle || f.shape == ShapeClass::kEllipse) return true;
  return has_corners(f.shape) && f.shape != ShapeClass::kPolygon &&
         least_corner_share(s.points, f.params.vertices, kCornerWindow) <
             rules.min_sharp_corner_share;
}

// A hexagon is within 7% of its radius of a circle, an octagon within 4%: far inside epsilon, and
// within a hand's wobble, so the circle may fit a drawn octagon a little more tightly than the
// octagon does; the turns tell them apart. A jittery circle may turn sharply somewhere by chance,
// and a polygon with its corners there fits it far more loosely than its circle
// (kSharpPolygonSlack).
void yield_to_sharp_polygon(const PreparedStroke& s, std::vector<Scored>& scored,
                            const RuleThresholds& rules) {
  double tightest = INFINITY; // the tightest sharp polygon snap
  for (const Scored& sc : scored) {
    if (sc.snap && sharp_polygon(s, sc.fit, rules)) {
      tightest = std::min(tightest, fit_measure(sc.candidate));
    }
  }
  for (Scored& sc : scored) {
    // The corner test last: it reads the stroke.
    if (!sc.snap || rules.sharp_polygon_slack * fit_measure(sc.candidate) < tightest ||
        !yields_to_sharp_polygon(s, sc.fit, rules)) {
      continue;
    }
    sc.snap = false;
    sc.candidate.rejected =
        "the stroke turns sharply at the corners of a polygon that fits it nearly as tightly, and "
        "not at this shape's (a polygon)";
  }
}

// A fat star's outline lies within epsilon of a pentagon; the hand turned at each of its corners,
// by more than the polygon's corners turn on average.
std::string extra_corner_implausibility(const PreparedStroke& s, const Fit& f) {
  const std::size_t k = f.params.vertices.size();
  if (sharp_turn_count(s, k + 1, regular_turn(k)) > k) {
    return "the stroke turns sharply at more corners than the polygon has (a star's outline)";
  }
  return {};
}

// A hexagon lies within epsilon of a quadrilateral through four of its corners, a heptagon of a
// hexagon: the corners left out are turns the hand made.
bool misses_a_corner(const PreparedStroke& s, const Fit& f, const RuleThresholds& rules) {
  const std::size_t k = f.params.vertices.size();
  if (k < 3 || k >= kMaxPolygonCorners) return false;
  if (!has_corners(f.shape) && f.shape != ShapeClass::kRegularPolygon) return false;
  return !sharp_turn_corners(s, k + 1, rules.min_missed_corner_turn * regular_turn(k + 1)).empty();
}

void yield_to_more_corners(const PreparedStroke& s, std::vector<Scored>& scored,
                           const RuleThresholds& rules) {
  std::size_t most = 0; // the most corners of a polygon snap
  for (const Scored& sc : scored) {
    if (sc.snap &&
        (sc.fit.shape == ShapeClass::kPolygon || sc.fit.shape == ShapeClass::kRegularPolygon)) {
      most = std::max(most, sc.fit.params.vertices.size());
    }
  }
  for (Scored& sc : scored) {
    if (!sc.snap || sc.fit.params.vertices.size() >= most || !misses_a_corner(s, sc.fit, rules)) {
      continue;
    }
    sc.snap = false;
    sc.candidate.rejected =
        "the stroke turns sharply at more corners than the shape has, and a polygon with more "
        "corners is a snap (a corner cut off)";
  }
}

std::vector<Fit> polygon_fits(const PreparedStroke& s, std::size_t k) {
  std::vector<Fit> out;
  auto add = [&out](std::optional<Fit> f) {
    if (f && std::isfinite(f->fit_error)) out.push_back(std::move(*f));
  };
  add(fit_polygon(s, k));
  const std::vector<PointD> turns = sharp_turn_corners(s, k, kLeastSeedTurnShare * regular_turn(k));
  if (turns.empty()) return out; // a round stroke: no fit from its turns
  add(fit_polygon_from_corners(s, turns));
  add(fit_polygon_through_turns(s, turns));
  add(fit_polygon_at_turns(s, turns));
  return out;
}

} // namespace penshape::recognize_detail
