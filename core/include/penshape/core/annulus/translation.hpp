#pragma once
// Annulus placement under translation (paper Sections 3.1, 3.2, 3.4, 5): containment decision,
// minimum-width optimisation, and max-cover with the anchored sweep of Fig. 3 and bucketing.
// Works for convex templates (kRound or kLinearized) and simple templates (kRound only).
// See annulus_template.hpp for the annulus, placements and the certification rules.
#include <cstddef>
#include <vector>

#include "penshape/core/annulus/annulus_template.hpp"

namespace penshape::annulus {

struct DecisionResult {
  // kYes: `placement` is verified exactly (all points in the delta-annulus).
  // kNo: no placement contains all points even with delta + margin (robust, see
  //      annulus_template.hpp).
  // kUndecided: delta is within the margin of the optimum and no exact witness was found.
  Answer answer = Answer::kUndecided;
  Placement placement; // meaningful with kYes
  double margin = 0.0; // the widening used for kNo
};

// Is there a translation whose delta-annulus contains all points? Anchored sweeps on the outer
// boundaries of hull points (convex templates) and the inner boundaries of all points, each
// intersecting the containing sets until empty. Throws InvalidInput for bad input (see
// validate_points / validate_delta; kLinearized with a simple template).
DecisionResult decide_translation(const TemplatePolygon& p, OuterOffset outer, double delta,
                                  const std::vector<PointD>& points, const Limits& limits = {});

struct MinWidthOptions {
  // Stop when delta_upper - delta_lower <= max(absolute_tolerance, relative_tolerance * scale),
  // scale = extent of the template plus extent of the points.
  double relative_tolerance = 1e-8;
  double absolute_tolerance = 0.0;
  std::size_t max_decisions = 200;
};

struct MinWidthResult {
  // The optimum delta* lies in [delta_lower, delta_upper].
  // delta_upper is certified exactly: `placement` puts every point in its delta_upper-annulus.
  // delta_lower is certified by a robust NO (no placement for delta_lower, see the margin).
  double delta_upper = 0.0;
  double delta_lower = 0.0;
  Placement placement;
  std::size_t decisions = 0; // decision runs used by the search
};

// The minimum delta for which a translate of the template's delta-annulus contains all points.
// (The paper's parametric search is replaced by a bisection on the exact-or-robust decision; each
// YES also lowers the upper bound to the width of its witness placement.)
MinWidthResult min_width_translation(const TemplatePolygon& p, OuterOffset outer,
                                     const std::vector<PointD>& points,
                                     const MinWidthOptions& options = {},
                                     const Limits& limits = {});

struct MaxCoverOptions {
  bool bucketing = true; // grid buckets the size of the outer offset's bounding box (Sec. 3.2)
};

struct MaxCoverResult {
  Placement placement;
  // Exactly verified: the points in the delta-annulus of `placement`, ascending indices. The
  // witness comes from a sweep with the annulus narrowed by the margin, so it is robust.
  std::vector<std::size_t> covered;
  // Robust upper bound on the optimum: the best count with the annulus widened by the margin
  // (duplicates counted). covered.size() == upper_bound certifies that the count is optimal; it
  // is smaller only when the best placements form a sliver thinner than the margin.
  std::size_t upper_bound = 0;
};

// A translation maximising the number of points in the delta-annulus (anchored sweep of both
// boundaries around every point, Fig. 3; duplicates are merged and weighted). O(n k m^2) time,
// O(n + m) space, k = points per 3x3 bucket block; a piece of a boundary that falls inside the
// other point's hole or outside its box costs O(1). Simple templates sweep every offset piece
// (2m segments, m circles) of every point: O(n k m^2) as in Section 5.
MaxCoverResult max_cover_translation(const TemplatePolygon& p, OuterOffset outer, double delta,
                                     const std::vector<PointD>& points,
                                     const MaxCoverOptions& options = {},
                                     const Limits& limits = {});

} // namespace penshape::annulus
