#pragma once
// Pieces of the translation algorithms shared with the on-line decision and the rotation search.
#include <algorithm>
#include <vector>

#include "penshape/core/annulus/translation.hpp"
#include "point_set.hpp"
#include "prepared_annulus.hpp"

namespace penshape::annulus::detail {

// A placement that lines up the bounding-box centres of template and points: the starting
// upper bound of the searches.
Placement centred_placement(const TemplatePolygon& p, const std::vector<PointD>& points);

// Bounding-box diagonal of the template plus that of the points.
double problem_scale(const TemplatePolygon& p, const std::vector<PointD>& points);

// Midpoint of the longest interval among per-piece sets, as a global curve parameter.
bool longest_interval_midpoint(const std::vector<IntervalSet>& sets, const Curve& curve, double& g);

// Smallest certified upper bound near `width` for `placement` (exact check, widening by margin).
double certify_width(const TemplatePolygon& p, OuterOffset outer, const Placement& placement,
                     double width, double margin, const std::vector<PointD>& points);

// A placement whose delta-annulus holds every point, verified exactly, from anchored sweeps with
// the annulus narrowed by the margin; false if none was found.
bool find_translation_witness(const TemplatePolygon& p, OuterOffset outer, double delta,
                              const std::vector<PointD>& points, Placement& placement);

// The minimum-width search shared by translation and rotation: bisection on the width with
// `decide(width, placement_so_far)`. A YES tightens the upper bound to its witness's certified
// width (usually below mid); a NO is a certified lower bound; an UNDECIDED only moves the search
// (the optimum is within the decision's margin of mid, not a certified bound).
template <typename Decide>
MinWidthResult bisect_min_width(const TemplatePolygon& p, OuterOffset outer,
                                const std::vector<PointD>& points, const MinWidthOptions& options,
                                Decide&& decide) {
  MinWidthResult res;
  res.placement = centred_placement(p, points);
  const double w0 = width_at(p, outer, res.placement, points);
  double hi = certify_width(p, outer, res.placement, w0, annulus_margin(p, w0, points), points);
  const double tol =
      std::max({options.absolute_tolerance, options.relative_tolerance * problem_scale(p, points),
                4.0 * annulus_margin(p, hi, points)});
  double lo = 0.0;
  double search_lo = 0.0;
  while (hi - search_lo > tol && res.decisions < options.max_decisions) {
    const double mid = 0.5 * (search_lo + hi);
    const DecisionResult r = decide(mid, res.placement);
    ++res.decisions;
    if (r.answer == Answer::kYes) {
      const double w = width_at(p, outer, r.placement, points);
      hi = std::min(mid, certify_width(p, outer, r.placement, w, r.margin, points));
      res.placement = r.placement;
    } else if (r.answer == Answer::kNo) {
      lo = search_lo = mid;
    } else {
      search_lo = mid;
    }
  }
  res.delta_upper = hi;
  res.delta_lower = lo;
  return res;
}

} // namespace penshape::annulus::detail
