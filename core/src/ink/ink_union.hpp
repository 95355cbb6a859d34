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
// in grid units (clipper_union_arithmetic).
//
// The sweep's decisions (Clipper 6.4.2's BuildIntersectList, E2InsertsBeforeE1, ProcessHorizontal,
// ProcessEdgesAtTopOfScanbeam) are taken on edges' x at a scanline, TopX = x_bot + Round(Dx (y -
// y_bot)), compared as integers; slope tests are exact (int128). The product carries gamma_5
// relative error (Dx's three roundings, y - y_bot's conversion, the product) of a value <= |dx|
// <= 2 M; Round (truncating val +- 0.5) errs by at most rho = 1/2 + u while 2 M (1 + gamma_5) <
// 2^52 (M < 2^50), by 1 beyond (val + 0.5 rounds itself). So TopX is within rho + 2 gamma_5 M
// of the edge's true x, exactly on the scanline. Round is monotone and shifts by integers, so
// TopX_e <= TopX_f implies x_e < x_f + 2 rho + 4 gamma_5 M (the 1 of two halves, or 2): Clipper's
// active edge list, sorted by TopX at each scanline (bubble sort in BuildIntersectList; insertion
// at local minima by Curr.X, ties by TopX at a top), differs from the true order only in pairs
// whose true horizontal gap there is below s = 2 rho + 4 gamma_5 M. The gap G = x_f - x_e of two
// edges is linear in y, so while Clipper keeps them in the wrong order between the true crossing
// and the scanline where it swaps them, it follows one edge where the exact union follows the
// other, at most max |G| <= s apart across them (a horizontal gap exceeds the distance across).
// A swap's point is IntersectPoint's (above) or, clamped into the scanbeam (ip.Y beyond an edge's
// top or the scanbeam's top, or below its bottom Curr.Y), TopX of one edge g at that scanline Y,
// within rho + 2 gamma_5 M of g (no further rounding: within the half diagonal and 64 u M counted
// above) and within that plus |G(Y)| of the other edge; |G(Y)| < s when Clipper's order was wrong
// there, and otherwise Y lies between the true crossing and the computed one, where the computed
// lines are within (4 + 8.5) gamma_3 M of each other across the flatter edge (above), so |G(Y)|
// is at most twice that. A horizontal edge's crossings are decided by TopX of the other edge
// against the horizontal's exact ends and placed at (TopX, y): wrong or off by at most rho + 2
// gamma_5 M. (BuildIntersectList's own clamp, when both edges' tops lie above the scanbeam's
// top, takes TopX of the left edge rather than the steeper one, so there the distance to the other
// edge is bounded across that edge only up to the ratio of the two edges' sqrt(1 + Dx^2); such a
// clamp needs a computed crossing far from the true one, i.e. nearly parallel edges, where the
// ratio is near 1. This case is probed by the tests, not closed by the argument.) Taking gamma_5
// <= 5.01 u and gamma_3 <= 3.01 u, 2 (12.5 gamma_3) + 4 gamma_5 < 128 u, each union adds
//     2 rho + 128 u M
// grid units beyond the above (clipper_union_sweep; one unit plus the doubles below 2^50 grid
// units, two units beyond).
//
// StrictlySimple's touching points: where two output edges have equal Curr.X, Clipper adds their
// point T = TopX to both (within s of both) and splits the contour there. A part beyond T whose
// vertices all lie on one line through T (a tip thinner than s at that scanline, however long)
// then has no area and is dropped (reproduced: the triangle (0,0) (1,0) (0,-1000) with another
// polygon's vertex at y = -600 loses its top 400 units). The dropped tip's apex V is a convex
// vertex of the union, hence of a piece, with angle alpha there at least the piece's; V's
// neighbour A on the tip's side lies at the scanline within s + rho + 2 gamma_5 M of T, and in
// the triangle A V T the law of sines gives |V T| <= |A T| when alpha >= pi / 2 (the angle at A is
// at most pi - alpha) and |A T| / sin(alpha) otherwise. So the final (StrictlySimple) union's
// terms (half diagonal, arithmetic, sweep) are multiplied by clipper_pinch_factor, 1 when every
// corner of every piece has an angle of pi / 2 or more (the ink's disk polygons and arcs, unless a
// small disk's rounded polygon has a sharp corner beside a larger one). A dropped notch of a hole
// adds only points within s of the union. This needs T to stay on the output: a piece thin
// enough to be pinched on every side vanishes whole (a triangle half a unit thick at its middle
// vertex's scanline), beyond any per-union term. So the ink polygon draws no disk smaller than
// four grid units: every piece then holds a disk of radius above 3 units (4 cos(pi / 8) less a
// half diagonal), whose cross-sections within 2.5 units of its centre are wider than s, so the
// part with area that T lies on survives.
//
// Still assumed: that Clipper's code carries out its sweep as written (its winding counts, output
// contours, joins and FixupOutPolygon, all exact integer logic). tests/core/ink_union_test.cpp and
// ink_union_sweep_test.cpp measure the distance of Clipper's union from the exact union with
// exact arithmetic on adversarial unions: the sweep's decisions take it beyond the old budget of
// a half grid diagonal and 64 u M (up to a whole unit: a triangle's apex cut at a scanline), and
// pinched tips beyond the sweep term by their corner's 1 / sin(alpha).
#include <clipper.hpp>

namespace penshape::ink_detail {

// Clipper's double arithmetic in one union, beyond its half grid diagonal of final rounding, in
// grid units, for coordinates of magnitude <= magnitude (grid units, < 2^62). Rounded up.
double clipper_union_arithmetic(double magnitude);

// Round's error in Clipper's TopX for coordinates of magnitude <= magnitude (grid units): rho
// above, 1/2 + 2^-53 below 2^50 and 1 beyond.
double clipper_topx_rounding(double magnitude);

// The sweep's decisions on rounded x in one union, in grid units (2 rho + 128 u M above), for
// coordinates of magnitude <= magnitude (grid units, < 2^62). Rounded up.
double clipper_union_sweep(double magnitude);

// How far a StrictlySimple union's pinched tips can reach, as a factor on its sweep term (and the
// half diagonal and arithmetic beside it): 1 when every convex corner of the pieces has an angle
// of at least pi / 2, else the largest 1 / sin(angle) over the sharper ones; infinite for a
// spike. Rounded up. The pieces keep their region on the left (outer rings counterclockwise,
// holes clockwise, as Clipper's offsets and the disk hulls are).
double clipper_pinch_factor(const ClipperLib::Paths& pieces);

// The union of `pieces` as the ink polygon takes it (non-zero fill, strictly simple output);
// false when Clipper refuses (coordinates out of its range).
bool clipper_union(const ClipperLib::Paths& pieces, ClipperLib::PolyTree& tree);

// That union given its pieces in parts (InkBuilder adds each chunk's as the chunk is built while
// the pen is down): Clipper adds paths one by one (AddPaths is a loop of AddPath), so adding the
// same pieces in the same order, in one call or several, leaves the same edges and local minima,
// and one execute() gives clipper_union's result bit for bit. execute() once only: Clipper sorts
// its minima in place, so pieces added after an execute() would not be in a fresh union's order.
class FedUnion {
 public:
  FedUnion();
  void add(const ClipperLib::Paths& pieces);
  bool execute(ClipperLib::PolyTree& tree); // false when Clipper refuses (as clipper_union)

 private:
  ClipperLib::Clipper clipper_;
};

} // namespace penshape::ink_detail
