#pragma once
// Annulus placement under translation and rotation (paper Section 3.3) for a convex template with
// the linearized outer offset. The rotation diagrams of the paper are swept along their 1-D
// skeleton: every family of placements with one point at a vertex of an annulus boundary, or two
// points on two boundary edges, parametrised by the angle theta; along each family the other
// points' containing sets are unions of theta-intervals (sine-curve boundaries). An optimal
// placement lies on such a family (the deepest cell of a diagram has a vertex), so the sweep finds
// it. Cost O(n^3 m^2) worst case for max-cover (full counts in every family: seconds for n = 100,
// m = 8); the decision and the minimum width stop a family at its first excluded point and are
// much faster. Not offered: the round outer offset with rotation (arcs give quartic equations).
// Degenerate inputs (parallel contact edges defining the only optimum) may be missed; the result
// is still a verified placement.
#include <vector>

#include "penshape/core/annulus/translation.hpp"

namespace penshape::annulus {

// Placement.tan_half_theta carries the exact rotation; `covered` is checked exactly for it.
MaxCoverResult max_cover_rotation(const TemplatePolygon& p, double delta,
                                  const std::vector<PointD>& points, const Limits& limits = {});

// Decision with rotation (same YES/NO/UNDECIDED rules as decide_translation).
DecisionResult decide_rotation(const TemplatePolygon& p, double delta,
                               const std::vector<PointD>& points, const Limits& limits = {});

// Minimum width with rotation, bisection on decide_rotation (rules of min_width_translation).
MinWidthResult min_width_rotation(const TemplatePolygon& p, const std::vector<PointD>& points,
                                  const MinWidthOptions& options = {}, const Limits& limits = {});

} // namespace penshape::annulus
