#pragma once
// Annulus placement under translation and rotation (paper Sections 3.3, 3.4, 5). A placement
// rotates the template by theta (stored exactly as u = tan(theta / 2), see annulus_template.hpp)
// and translates it. Certification rules are those of the translation functions: every YES,
// placement and covered set is checked exactly; NO answers and upper bounds are robust (they hold
// even for delta + margin); when the search stops at its resolution or budget the answer is
// UNDECIDED / a certified interval, never a guess.
//
// Methods (RotationOptions::method; kAuto picks 1 for kLinearized, 3 for kRound):
//
// 1. Rotation diagrams (convex template, kLinearized only). The diagrams of the paper are swept
//    along their 1-D skeleton: every family of placements with one point at a vertex of an annulus
//    boundary, or two points on two boundary edges, parametrised by theta; along each family the
//    other points' containing sets are unions of theta-intervals (sine-curve boundaries). An
//    optimal placement lies on such a family, so the sweep finds it. O(n^3 m^2) worst case for
//    max-cover (kAuto uses it up to RotationOptions::diagram_max_work, method 3 above); the
//    decision and the minimum width stop a family at its first excluded point and are much faster.
//    Degenerate inputs (parallel contact edges defining the only optimum) may be missed; the result
//    is still a verified placement. (The arcs of the round offset would give quartic equations
//    here; methods 2 and 3 avoid them.)
//
// The bound behind methods 2 and 3. Rotating the points by -theta about their centroid c instead
// of rotating the template gives the same placements:
//     q'(theta) = c + R(-theta)(q - c);  translation t of the q'  <->  placement
//     (theta, c - R(theta)(c - t)) of the template.
// For angles a, b: |R(a)v - R(b)v| = 2 |v| |sin((a - b) / 2)| <= |v| |a - b| (chord <= arc). So if
// every angle of an interval is within w of the sample angle tm, every rotated point stays within
// rho_q w of q'(tm), rho_q = |q - c| <= rho. The annulus measure (least delta whose annulus holds
// the point: the distance to the template boundary, or |max_k n_k.x - h_k| for the linearized
// offset, unit normals) is 1-Lipschitz in the point. Hence, for every placement with its angle in
// the interval, each point's measure differs from its measure at angle tm (same t) by at most
// rho_q w. Rounding of the rotated points and of the measures is covered by the slack
// s = 1e-9 * (coordinate magnitude + template extent + delta), far above a few ulps.
//
// 2. Branch and bound over the angle with the translation solvers (kRound or kLinearized, convex
//    or simple templates). For an angle interval (sample tm, reach w):
//      - a robust translation NO at tm for delta + margin + rho w + s is a NO on the interval;
//      - the interval's max-cover is <= the translation upper bound at tm for that delta;
//      - the interval's minimum width is >= the translation delta_lower at tm - rho w - s;
//      - a translation YES / witness at tm is a placement (checked exactly with the rational
//        rotation u = tan(tm / 2)).
//    The most promising interval is halved until the bounds meet, its half-width falls below
//    angle_resolution, or max_evaluations translation solves are spent.
//
// 3. Branch and bound over cells of (tx, ty, theta), t the translation of the rotated points (any
//    template and offset). A cell (translation half-diagonal r_t, angle reach w) moves point q by
//    at most r_t + rho_q w from its position at the cell's centre. Max-cover and decision: per
//    cell the points are certainly covered everywhere (measure + r_t + rho_q w + s <= delta),
//    certainly uncovered (measure - r_t - rho_q w - s > delta + margin) or open; children inherit
//    the first two groups and re-examine only the open points, so deep cells cost little. The
//    cell's bound is covered + open; its centre is a candidate placement, checked exactly. Min
//    width: the cell's lower bound is max over points of (measure - r_t - rho_q w - s); a point
//    whose largest possible measure is below that is never the widest in the cell and is dropped.
//    Cells are explored best bound first and dropped when they cannot beat the best verified
//    answer; cells below both resolutions, or beyond max_cells, are left with their bounds.
//    The max-cover bound counts a point coverable somewhere in the cell, not at one placement, so
//    a cell on the border of two equally good placements resolves only at the resolution: the
//    reported upper_bound can then exceed covered.size() (both remain certified).
//
// Simple (non-convex) templates: methods 2 and 3 with kRound (the paper's Section 5 is translation
// only; this is the same Lipschitz search around its translation solvers and measure).
#include <cstddef>
#include <vector>

#include "penshape/core/annulus/translation.hpp"

namespace penshape::annulus {

enum class RotationMethod { kAuto, kDiagram, kAngleSearch, kCellSearch };

struct RotationOptions {
  RotationMethod method = RotationMethod::kAuto; // kDiagram needs a convex template, kLinearized
  // Branch and bound (methods 2 and 3): intervals / cells whose angle reach is below this
  // (radians) and, for cells, whose translation half-diagonal is below translation_resolution
  // times the problem scale, are not split further; their bounds are reported as they stand.
  double angle_resolution = 1e-9;
  double translation_resolution = 1e-9;
  // Budgets: translation solves (method 2), cell evaluations (method 3). Exhausting one ends the
  // search with honest bounds (UNDECIDED, delta_lower < delta_upper, upper_bound > covered).
  std::size_t max_evaluations = 2000;
  std::size_t max_cells = 2'000'000; // about a second and 30 MB at n = 1,000
  // kAuto, kLinearized max-cover: method 1 while n^3 m^2 (n distinct points, m template
  // vertices) is at most this (about a second), method 3 above.
  double diagram_max_work = 64e6;
};

// A placement maximising the points covered. Placement.tan_half_theta carries the exact rotation;
// `covered` is checked exactly for it; `upper_bound` is a robust bound on the optimum.
// Throws InvalidInput for bad input, a simple template with kLinearized, or more than
// Limits::max_rotation_points points.
MaxCoverResult max_cover_rotation(const TemplatePolygon& p, OuterOffset outer, double delta,
                                  const std::vector<PointD>& points,
                                  const RotationOptions& options = {}, const Limits& limits = {});

// Decision with rotation (same YES/NO/UNDECIDED rules as decide_translation).
DecisionResult decide_rotation(const TemplatePolygon& p, OuterOffset outer, double delta,
                               const std::vector<PointD>& points,
                               const RotationOptions& options = {}, const Limits& limits = {});

// Minimum width with rotation (rules of min_width_translation: delta_upper certified exactly by
// `placement`, delta_lower by robust NOs / Lipschitz bounds; the search stops when they are within
// the tolerance of `options`, or at the resolution / budget). Method 1: bisection on the diagram
// decision; method 2: min_width_translation at each sample angle; method 3: cells. `decisions`
// counts decisions (1, 2) or cells (3).
MinWidthResult min_width_rotation(const TemplatePolygon& p, OuterOffset outer,
                                  const std::vector<PointD>& points,
                                  const MinWidthOptions& options = {},
                                  const RotationOptions& rotation = {}, const Limits& limits = {});

} // namespace penshape::annulus
