#pragma once
// The classifier shared by recognize() and the live recognizer: fit every family, certify the
// plausible fits, and choose the simplest certified shape.
#include <vector>

#include "recognize/fitting/fit.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {

// A stroke is closed when its end comes back near its start (recognize.hpp, "Classes"): only
// then can a closed shape certify, and only then are closed families tried; open strokes try
// the open families (segment, polyline, arc).
bool is_closed(const PreparedStroke& s, double epsilon);

// A family: the class, and the vertex count for polylines and regular polygons (else 0).
struct Family {
  ShapeClass shape = ShapeClass::kFreeform;
  std::size_t vertices = 0;
  friend bool operator==(const Family&, const Family&) = default;
};
Family family_of(const Fit& f);

// Whether the class is a convex polygon (triangle, quadrilaterals, regular polygon): those snaps
// are placed by the minimum-width annulus and followed live by the on-line annulus decision.
bool convex_polygon(ShapeClass c);
// Whether the class has corners a polygon fit placed (triangle, quadrilaterals, polygon): they
// must be corners (classifier.cpp, corner rules).
bool has_corners(ShapeClass c);

// All family fits for a prepared stroke (families that do not apply are left out), except the
// families in `skip`.
std::vector<Fit> fit_all(const PreparedStroke& s, const RecognizerConfig& config, double epsilon,
                         const std::vector<Family>& skip = {});

// The thresholds of the plausibility rules that the bench sweeps per held-out writer
// (recognize_bench --rule-folds); everything else reads thresholds.hpp directly.
struct RuleThresholds {
  double diamond_skew = kDiamondSkew;
  double max_backtrack = kMaxBacktrack;
  double min_sharp_corner_share = kMinSharpCornerShare;
  double min_fitted_corner_share = kMinFittedCornerShare;
  double min_model_corner_share = kMinModelCornerShare;
  double sharp_polygon_slack = kSharpPolygonSlack;
  double min_missed_corner_turn = kMinMissedCornerTurn;
  double min_flat_corner_turn = kMinFlatCornerTurn;
};

// A fit with its certificate, plausibility and rank.
struct Scored {
  Fit fit;
  Candidate candidate;
  double rank = 0.0;
  bool snap = false; // certified and plausible
};

// How tightly a candidate fits the stroke: its certified bound plus its rms weighted as in the
// rank's fit term.
double fit_measure(const Candidate& c);

// Certifies the fits (skipping those whose fit error already exceeds the tolerance by far) and
// checks their plausibility; sorted snaps first, then by rank.
std::vector<Scored> evaluate(const PreparedStroke& s, std::vector<Fit> fits, double epsilon,
                             double pen_radius, const RecognizerConfig& config,
                             const RuleThresholds& rules = {});
// Ranks candidates evaluated apart (the live recognizer's survivors and fresh fits) as one
// evaluate() call would: a sharp polygon among them overrules the round and blunt shapes it fits
// nearly as tightly as (kSharpPolygonSlack); sorted as evaluate() sorts.
void settle(const PreparedStroke& s, std::vector<Scored>& scored, const RuleThresholds& rules = {});
// Certifies the snaps (the first, path-certified plausible candidates) again on the inks, best
// rank first, until one passes: it is the winner; those that failed are no longer snaps, those
// after the winner keep their path certificates. Re-sorted as evaluate() sorts.
struct InkRegion;
void confirm_on_ink(const InkRegion& q, std::vector<Scored>& scored);
// The recognition from evaluated candidates.
Recognition choose(std::vector<Scored> scored, double epsilon, double pen_radius);

// Model complexity used to prefer simpler shapes (number of free parameters).
double degrees_of_freedom(const Fit& fit);
// Every family fit_all can produce, and the lowest rank a candidate of a family can have.
std::vector<Family> all_families(const RecognizerConfig& config);
double minimum_rank(const Family& family);
// Whether a snap of the family can win over a better-ranked snap (a polygon drawn with sharp
// corners wins over the circle whose band holds it): no rank bound may skip its fit.
bool wins_on_corners(const Family& family);

// choose_tolerance()'s rule from the samples' bounding box alone (lo, hi: its corners), for
// callers that already hold the box, e.g. the grouper's candidate unions.
ToleranceChoice tolerance_for_box(PointD lo, PointD hi, const RecognizerConfig& config);

} // namespace penshape::recognize_detail
