#pragma once
// Candidate construction with Clipper 6.4 (int64 offsets and Booleans). Clipper rounds every
// computed vertex to the grid, so nothing built here is trusted: its results are only
// candidates that certificate.hpp verifies independently (see README.md).
#include <vector>

#include "int_geometry.hpp"

namespace penshape::fast {

struct IPolygon {
  IRing outer;  // counterclockwise
  IRings holes; // clockwise
};
using IRegion = std::vector<IPolygon>;

IRings flatten(const IRegion& region);

// Which spokes of the raw path are replaced by the direct step v + delta n0 -> v + delta n1:
// kKeep none (the former path); kCovered those `spoke_is_covered` (raw_offset.hpp) proves change
// nothing (the positive-winding region is the same wherever the rings' winding number is >= 0:
// every region of simple, consistently nested rings, and the complement of one within a box);
// kNarrow also every spoke of a corner that turns by at most 90 degrees. kNarrow is for candidates
// that are checked afterwards: near v both edges' quadrilaterals cover the dropped triangle (v, a,
// b), but farther out only the ring's other pieces may, so the region can lose slivers along a
// dropped spoke where the edges beside it are shorter than delta.
enum class Spokes { kKeep, kCovered, kNarrow };

// Offset (delta > 0) or inset (delta < 0) of the region bounded by `rings` (nonzero winding)
// with round joins: arc vertices on the circle of radius |delta|, chords at distance at least
// |delta| - arc_tolerance (Clipper's own tolerance parameter is tightened to guarantee it).
// Straight parts are exact up to grid rounding. Insets are the outward offset of the complement
// (OffsetMode::kStriped) or ClipperOffset's (kFormer). `spokes`: which spokes of reflex corners
// the raw path leaves out (raw_offset.hpp; kStriped only): kCovered keeps the region, kNarrow
// is for candidates only.
IRegion offset_round(const IRings& rings, double delta, double arc_tolerance,
                     Spokes spokes = Spokes::kCovered);

// How offsets are computed: kStriped (the default) builds the raw path of insets too (as the
// outward offset of the complement) and unions large raw paths stripe by stripe
// (stripe_union.hpp); kFormer insets with ClipperOffset and unions in one sweep. Both have the
// bounds stated below; the bench shows them side by side.
enum class OffsetMode { kStriped, kFormer };
void set_offset_mode(OffsetMode mode);
[[nodiscard]] OffsetMode offset_mode();

// Whether the union of raw offset paths turns paths wider than tall a quarter turn for Clipper's
// sweep (stripe_union.hpp; the default); false keeps them as given, for the bench's
// side-by-side figure. The regions are the same up to Clipper's rounding.
void set_turn_wide_paths(bool turn);

// Vertices on a full circle of radius |delta| at this tolerance (at most; joins use fewer).
double round_join_steps(double delta, double arc_tolerance);

// subject minus clip (nonzero winding for both).
IRegion difference(const IRings& subject, const IRings& clip);

// Douglas-Peucker on every ring (tolerance in grid units), then a nonzero union so the result
// is a valid region again. Theorem 5's observation in practice: the many short edges of dents
// left by an inset collapse into chords.
IRegion simplify(const IRings& rings, double tolerance);

// Douglas-Peucker on every ring of every polygon, keeping the outer/hole structure and skipping
// the union (the caller checks the result and falls back to simplify() if it is not simple).
IRegion simplify_rings_only(const IRegion& region, double tolerance);
inline IRegion simplify(const IRegion& region, double tolerance) {
  return simplify(flatten(region), tolerance);
}

} // namespace penshape::fast
