#pragma once
// The ink-level certificate: a certified upper bound on the Hausdorff distance between a clean
// shape's ink C ⊕ D_r and the true ink T of a stroke (the exact region the pen disks swept,
// pressure-varying radii allowed), computed from the stroke's ink polygon Q.
//
// Why (and not the path certificate of recognize.hpp): H(path, clean path) bounds the distance of
// the inks only when the stroke's ink is path ⊕ D_r with one radius. With pressure the ink is
// not, and Q is what the user saw. Here:
//     H(C ⊕ D_r, T) <= H(C ⊕ D_r, Q) + H(Q, T) <= H(C ⊕ D_r, Q) + Q.hausdorff_bound     (1)
// (the triangle inequality of the Hausdorff distance; ink.hpp bounds H(Q, T)).
//
// H(C ⊕ D_r, Q) = max(S1, S2) with S1 = sup_{x in C⊕D_r} d(x, Q) and S2 = sup_{q in Q}
// d(q, C ⊕ D_r) = sup_{q in Q} max(0, d(q, C) - r). Both are sups over 2-D regions of
// 1-Lipschitz functions that can peak inside a region (d(., Q) inside a hole of Q, d(., C)
// at a circle's centre), so they are sampled on the square grid G = {o + (i h, j h)} covering
// both regions' boxes (o = Q's lowest corner):
//   - every point x of the plane within the box has a grid point g with |x - g| <= h/sqrt(2);
//   - S1: if x is in C ⊕ D_r then d(g, C) <= r + h/sqrt(2), and d(x, Q) <= d(g, Q) + h/sqrt(2).
//     So S1 <= max{ d(g, Q) : g in G1 } + h/sqrt(2) for any G1 containing every g with
//     d(g, C) <= r + h/sqrt(2). G1 is chosen with an exact distance for polylines and circular
//     arcs; for an ellipse a point is left out only when proven farther (an algebraic bound on
//     the ellipse equation, then the chords of the ellipse sampled with arc-length steps hs =
//     h/4, coarser for curves longer than 20,000 such steps: d(g, ellipse) >= d(g, chords) -
//     hs/2). Taking more points only raises the maximum.
//     d(g, Q) = 0 when g is inside Q (parity of the crossings of the grid row with Q's edges),
//     else bounded by the least of the certified upper bounds to Q's edges.
//   - S2: if q is in Q then d(g, Q) <= h/sqrt(2) and max(0, d(q, C) - r) <= max(0, d(g, C) - r)
//     + h/sqrt(2). So S2 <= max{ max(0, d(g, C) - r) : g in G, d(g, Q) <= h/sqrt(2) } +
//     h/sqrt(2), with d(g, C) bounded from above (exact for polylines and circular arcs; the
//     distance to a point ON the ellipse otherwise).
//   - The grid covers Q's box and the clean ink's box (polylines: from the vertices; curves:
//     from samples with steps hs, grown by hs/2).
//   - A clean ink whose box reaches more than epsilon + 2h beyond Q's box has a point farther
//     than epsilon from Q and cannot certify; its bound is the diagonal of the union of the
//     boxes (no two points of the regions are farther apart), plus Q.hausdorff_bound.
// Arithmetic: doubles only propose (which grid points to visit, the nearest edge, the foot point
// on C). Every selection that leaves a grid point out is proven in interval arithmetic with
// directed rounding (CGAL Interval_nt, through core/src/geometry/distance_kernel.hpp): a point
// is left out of G1 only when a lower bound on d(g, C) exceeds r + h/sqrt(2) (polylines: each
// segment's box, then its interval distance; arcs: the distance to the circle, or to the nearer
// end when g is certainly outside the arc's sector; ellipses: the algebraic bound, then the
// chords through enclosed points at parameter steps dt, d(g, ellipse) >= d(g, chords) -
// speed dt / 2 - the boxes' reach), and out of the Q side only when every edge is certainly
// farther than h/sqrt(2). Every value taken into a maximum is an interval upper bound (the
// distance to the proposed edge, or to the proposed foot point with sin and cos enclosed within
// 2 ulps). Inside/outside comes from the row's crossings, each an interval: a grid point whose
// crossing interval is not certainly left or right of it is treated as outside (its distance to
// the nearest edge is then bounded, not assumed 0). Q's vertices are rounded to doubles (Q');
// H(Q, Q') is at most the largest vertex rounding (a winding-number argument: a point of the
// symmetric difference is passed by the boundary moving from Q to Q'), computed rounded up and
// added. The grid points are the doubles o + i h (the product and the sum rounded), so their
// gaps are measured, not assumed: h/sqrt(2) stands for sqrt(A^2 + B^2)/2 rounded up, A and B the
// widest gaps between neighbouring grid lines actually used (every point of the box is within
// half its cell's diagonal of a corner). The curve's end parameter t0 + sweep is rounded, so
// the curve C' sampled may run past the true C by H(C, C') <= the speed times that rounding: it
// widens the selection of G1 and is added to the S2 estimate (measured against C').
// No margin decides anything. Q.hausdorff_bound (ink.hpp) is taken as the ink module gives it.
// Hence
//     bound = max(S1 estimate, S2 estimate) + h/sqrt(2) + H(Q, Q') + Q.hausdorff_bound
//           >= H(C ⊕ D_r, T),
// and the certificate holds when bound <= epsilon. The bound exceeds the true H(C ⊕ D_r, Q) by
// at most about 2 h (the grid's h/sqrt(2) twice, once in the selection and once in the value,
// plus hs/2 for ellipses) plus Q.hausdorff_bound.
//
// Pruning (the same maxima, bit for bit, as visiting every grid point): each grid point g gets a
// selection and a value computed from g alone (never from the running maximum or a visiting
// order): the S1 value is min over Q's edges of a certified upper bound to the edge (computed
// exactly: a proposed edge's bound u, then only edges whose box comes within u), the S2 value is
// the least of the shape's bounds (polylines: over every segment; arcs: the ray's distance when
// certainly inside the sector, else the nearer end; ellipses: the foot's distance and the
// chords' bound). The grid is visited in aligned blocks (16 x 16 points, then quadrants down to
// 2 x 2, each level in decreasing order of how far a block may raise a maximum, so that good
// maxima come early). For a block, the grid points' box B (an interval point: [x_i0, x_i1] x
// [y_j0, y_j1], the grid's own doubles) is put through the SAME interval expressions as a point.
// Interval arithmetic with directed rounding is inclusion-monotone, and each term is used only
// under a condition certain for B, hence for every point of B (core/src/recognize/
// ink_box_bounds.hpp); so for every g in B, as computed: lower bounds at g >= at B and upper
// bounds at g <= at B. Hence
//   - a side that proves "no point of B selected" at B (S1: the shape certainly farther than
//     r + h/sqrt(2), or every row of B certainly inside Q'; S2: every row of B certainly outside
//     Q' with no crossing interval meeting it, and every edge certainly farther than h/sqrt(2))
//     selects none of B's points, as computed at each;
//   - a bound at B on the values (one edge's or one chord's bound at B, which is above the least
//     one at each point) at most the maximum already reached over real grid points means no
//     point of B can raise that maximum.
// A pruned point would not have changed either maximum, and a maximum does not depend on the
// order of its terms: `bound` is the flat scan's, to the bit. A point whose cheap bound (one
// edge; the foot alone) is already at most the running maximum is skipped for the same reason.
//
// Spacing: h = epsilon / 10, coarsened so that at most 250,000 grid points are sampled (Q's box
// grown by 1.3 epsilon each side); with the default tolerance rule a stroke's box is about 8
// epsilon wide, about 7,000 grid points, of which pruning evaluates a few hundred.
#include "penshape/core/ink.hpp"
#include "penshape/core/recognize.hpp"

namespace penshape {

// The certificate of the clean shape (class and parameters as recognize() reports them: vertices
// of segments, polylines and polygons, which are closed; centre and radius of circles; centre,
// radius, start and sweep of arcs; centre, radius_x along `rotation`, radius_y across it for
// ellipses) drawn with pen radius `pen_radius` against the stroke's ink `ink` (same unit).
// method "ink", sample_spacing = h. Throws InvalidInput for freeform, an empty ink polygon,
// non-finite or negative radius, a non-positive epsilon, or degenerate parameters (no vertices,
// non-positive radii).
Certificate certify_ink(const InkPolygon& ink, ShapeClass shape, const ShapeParams& params,
                        double pen_radius, double epsilon);

} // namespace penshape
