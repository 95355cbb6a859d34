#pragma once
// Pieces of the translation algorithms shared with the on-line decision and the rotation search.
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

} // namespace penshape::annulus::detail
