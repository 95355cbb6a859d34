#pragma once
// The ink polygon's unions in Clipper 6.4 (int64; internal to core/src/ink.cpp and its tests), and
// what Clipper's own double arithmetic adds to the ink bound (ink.hpp) for each union.
//
// A union's output vertices are input vertices (exact) or intersection points of two input edges
// that the sweep found crossing in a scanbeam (ClipperLib's IntersectPoint; on a horizontal edge,
// TopX of the other edge at its height). IntersectPoint works in doubles: each edge's inverse slope
// Dx = dx / dy (three roundings: two int64 -> double conversions and the division), the
// intercepts b = x_bot - y_bot * Dx (four roundings), q = (b2 - b1) / (Dx1 - Dx2) (three), then
// y = Round(q) and x = Round(Dx * q + b) along the steeper edge (two more); a point outside the
// scanbeam is clamped to it and its x taken as TopX = x_bot + Round(Dx * (y - y_bot)). With
// u = 2^-53, gamma_n = n u / (1 - n u) and M the largest coordinate magnitude (grid units), the
// error analysis, measured across each edge (horizontal gaps divided by sqrt(1 + Dx^2) of the
// flatter edge, which is the larger factor since |Dx1| <= |Dx2|; (2 + 2t) / sqrt(1 + t^2) <= 2
// sqrt(2)):
//   - the computed line x = x_bot + Dx (y - y_bot) leaves the true edge, within its height, by
//     at most gamma_3 |dx| <= 2 gamma_3 M, and by 4 gamma_3 M a unit beyond it;
//   - the two computed lines' gap at q is |Dx1 - Dx2| |q - y'| <= 3 gamma_3 (B1 + B2), B = |x_bot|
//   +
//     |y_bot| |Dx|, which is at most 8.5 gamma_3 M across the flatter edge;
//   - x along the steeper line errs by 2 gamma_3 (M |Dx1| + B1) horizontally, <= 4.5 gamma_3 M
//     across either edge;
//   - TopX errs by at most gamma_5 2 M horizontally;
// so before its final rounding the point lies within 19 gamma_3 M < 64 u M of both edges
// (4 + 8.5 + 4.5 + 2 = 19 in units of gamma_3 M), and the final rounding (Round: half a unit per
// coordinate below 2^52, one unit above, where a double has no half units) moves it half a grid
// diagonal, counted in ink.hpp's grid term, or a whole diagonal above 2^52. Per union, this adds
//     64 u M, plus sqrt(2) / 2 when M >= 2^52,
// in grid units (clipper_union_arithmetic). What this does NOT prove: that Clipper's sweep joins
// these points into the boundary of the exact union (its combinatorics: an intersection clamped
// to a scanbeam's end on a nearly horizontal edge can lie far along that edge from the crossing,
// within a unit of it vertically). That is Clipper's own correctness, which the ink bound
// assumes; tests/core/ink_union_test.cpp measures the distance of Clipper's union from the exact
// union with exact arithmetic on adversarial unions, where grid rounding alone falls short.
#include <clipper.hpp>

namespace penshape::ink_detail {

// Clipper's double arithmetic in one union, beyond its half grid diagonal of final rounding, in
// grid units, for coordinates of magnitude <= magnitude (grid units, < 2^62). Rounded up.
double clipper_union_arithmetic(double magnitude);

// The union of `pieces` as the ink polygon takes it (non-zero fill, strictly simple output);
// false when Clipper refuses (coordinates out of its range).
bool clipper_union(const ClipperLib::Paths& pieces, ClipperLib::PolyTree& tree);

} // namespace penshape::ink_detail
