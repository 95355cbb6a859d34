#pragma once
// The certified stroke recognizer: name the shape a pen stroke was meant to be, and snap to it
// only when the snap is proven close to what was drawn.
//
// What "proven" means (the certificate). Let A be the stroke's pen path (the samples joined by
// straight segments) and B the clean shape's path (segment, polyline, closed polygon, circle,
// ellipse or arc). Drawn with the same pen disk D (radius r), the inks are A ⊕ D and B ⊕ D, and
//     H(A ⊕ D, B ⊕ D) <= H(A, B)                                                        (1)
// (a point a + d of A ⊕ D lies within |a - b| of b + d, with b the nearest point of B to a; the
// same the other way round). So an upper bound on the Hausdorff distance H(A, B) of the two
// *paths* bounds the distance of the two *inks*. We bound each one-sided distance by sampling:
//   - sup_{a in A} d(a, B): every segment of A is sampled with spacing <= h, so every a in A is
//     within h/2 of a sample s; d(., B) is 1-Lipschitz, hence d(a, B) <= d(s, B) + h/2. For
//     polygonal B, d(s, B) is the exact point-segment distance; for a circular arc it is the
//     exact | |s - c| - R | (or the distance to an end); for an ellipse it is |s - e| for a
//     point e ON the ellipse (Newton's foot point), which can only over-estimate d(s, B).
//   - sup_{b in B} d(b, A): B is sampled with arc-length spacing <= h (for an ellipse the speed
//     |B'(t)| <= max(a, b) bounds the arc length of a parameter step), and d(b, A) <= d(s, A) +
//     h/2 with d(s, A) the exact distance to the polyline A.
// Every distance is computed in double precision; a margin of 1e-13 times the largest coordinate
// magnitude plus 1e-9 times the drawing's extent (far above the rounding error of these few
// operations, a small multiple of 2.2e-16 times the magnitude) is added.
// The certified bound is therefore  bound = max(both one-sided maxima) + h/2 + margin  >= H(A, B)
// >= H(inks) by (1). A stroke snaps to a clean shape only when bound <= epsilon.
//
// Dense strokes (thinning). A 1 kHz tablet sends thousands of samples per stroke; the cost must
// follow the drawing, not the sample rate. Before fitting and certifying, the path A (every
// distinct sample) is thinned to a sub-path A' (Douglas-Peucker with tolerance
// tau = thin_tolerance_fraction * epsilon, on windows of at most 128 samples whose ends are
// kept, so the worst case stays linear; first and last samples kept). Claim: H(A, A') <= tau.
//   - sup_{a in A} d(a, A') <= tau: each dropped sample v_j lies between two kept samples v_i,
//     v_k (i < j < k) and Douglas-Peucker dropped it only because d(v_j, [v_i, v_k]) <= tau;
//     every edge [v_j, v_j+1] of A lies between the same kept pair, so both its ends are within
//     tau of the chord [v_i, v_k], and the distance to a segment (a convex set) is a convex
//     function, hence at most tau along the whole edge.
//   - sup_{b in A'} d(b, A) <= tau: let b be on the chord [v_i, v_k], b = v_i + t (v_k - v_i).
//     The sub-path A[i..k] is continuous from v_i (projection parameter 0 onto the chord's
//     line) to v_k (parameter 1), so by continuity some point a of it projects exactly onto b;
//     then |a - b| = d(a, [v_i, v_k]) <= tau by the first part. (A degenerate chord v_i = v_k
//     is a point of A itself.)
// So, by the triangle inequality for the Hausdorff distance,
//     H(A, B) <= H(A', B) + H(A, A') <= H(A', B) + tau,
// and the path certificate bounds H(A', B) as above and adds tau (plus one more rounding margin
// for the thinning's own distance tests). Everything else (fits, plausibility, ranking) may use
// A': the fit points, size, length and closure still come from every sample. The distance to
// the thinned stroke is looked up in a uniform grid of its segments. The ink certificate works
// on the ink polygon and is not affected. thin_tolerance_fraction = 0 turns both off (the
// previous behaviour, kept as the benchmark baseline).
//
// Tolerance epsilon (RecognizerConfig): it follows the drawing, not the pen,
//     epsilon = min(f * size + k * r, f_max * size),
// where size is the diagonal of the stroke's (or group's) bounding box and r the pen radius:
// f = tolerance_size_fraction (a hand's wobble grows with the size of what it draws), k =
// tolerance_pen_radii (the ink's own radius: a pressure pen's ink varies by up to r around the
// clean ink drawn with r), f_max = max_tolerance_fraction (so a wide pen on a small mark never
// snaps coarsely). f and f_max are derived from real strokes by `recognize_bench
// --derive-tolerance` on ../shared/data/strokes (the $1 logs and other people's gestures, 102
// writers): f_max the largest epsilon / size whose non-shape snaps plus one standard error over
// the writers stay <= 1.5%, f the smallest within one point of its shape rate. It derives 0.125 /
// 0.135 today, the shipped values. Measured there (recognize_bench --accuracy-only): the $1
// default run 99.1% of shapes right, 0.7% non-shape snaps, the gestures 98.9% / 0.6%; held out
// (each writer at the fractions derived without them) $1 99.1% / 0.8%, gestures 98.9% / 0.6%;
// every cell of 15..150 mm by 0.25..2 mm pens at the shipped defaults >= 97.4% / <= 0.7% on $1,
// >= 98.7% / <= 0.6% on the gestures. The derivation counts single strokes: arrows are fitted
// within their own share of epsilon (group_recognize.hpp, "Arrows"). When no pen radius is
// given, r = default_pen_radius_fraction * size. Every entry point (recognize, the live
// recognizer, the grouper, penshape recognize and snap, the daemon, the board through the
// daemon) calls choose_tolerance(); an explicit tolerance overrides the rule.
//
// Classes. A stroke is closed when its end comes back near its start: the last point is within
// 2 epsilon of the first fifth of the path, or the first point within 2 epsilon of the last fifth
// (an overshooting circle passes its start). Closed strokes try the closed families (triangle,
// quadrilateral, rectangle, square, diamond, regular polygon, polygon of 5..8 corners, circle,
// ellipse), open strokes the open ones (segment, polyline of 2..max_polyline_segments segments,
// arc).
//
// A snap needs the certificate AND a plausible reading (so handwriting and gestures stay ink):
//   - the shape is drawn once: the stroke is at most 1.6 times as long as the clean shape
//     (scribbles and writing go over the same region many times), and its total absolute
//     turning (on 16 points along it, ignoring turns within epsilon / 4 of a straight run) exceeds
//     the shape's by at most half a turn (writing wiggles); it is traced one way round: its
//     points, placed in order along the shape's path, run back over at most 10% of it (a stem
//     drawn down and up again, as in a P or a note, only stays in the shape's band);
//   - straight open shapes (segment, polyline) must certify within straight_fraction * epsilon
//     (people draw straight strokes far more precisely than round ones; a curve that merely
//     stays near a few segments is a letter or a brace, not a polyline);
//   - every interior corner of an open polyline is at least epsilon / 2 from the chord of its
//     neighbours;
//   - an open polyline must not cross itself (x, alpha, delete marks are gestures);
//   - a polygon of 5..8 corners does not cross itself (a star drawn in one stroke is no polygon);
//   - a diamond (a rhombus in any orientation: centre, angle, two half-diagonals) has angles more
//     than 15 degrees from right ones (1.5 times the tidy-up's right-angle slack); closer, it is
//     a square: a square standing on a corner is a square, turned 45 degrees;
//   - every side of a polygon (triangle, quadrilateral, rectangle, square, diamond, polygon) is at
//     least epsilon long, and every corner is at least epsilon from the chord of its two neighbours
//     (otherwise the polygon with one corner less says the same within tolerance: a corner drawn
//     round, or a bump on a side); epsilon / 2 for a polygon of 5..8 corners drawn sharp (below),
//     epsilon / 4 at one of its corners where the stroke turns by 0.6 of a regular polygon's
//     turn or more (a lump of the hand flattens an octagon's corner, not the turn made there);
//   - a regular polygon's corners must stand out from its circumcircle by at least epsilon / 2
//     (R (1 - cos(pi / n)) >= epsilon / 2), or the circle says the same thing more simply, unless
//     the stroke turns sharply at them;
//   - corners drawn sharp: at a corner of a (regular) polygon of 5..8 corners, the stroke turns,
//     between chords a quarter of the shorter side beside it either way, by at least 0.5 of the
//     polygon's turn there (a circle through the corners turns about 0.25; the corner where the
//     stroke starts and ends is not read). Such a polygon is the snap and no circle or ellipse is,
//     nor a shape of fewer corners the stroke does not turn sharply at: a hexagon lies within 7%
//     of its radius of a circle, an octagon within 4%, far inside epsilon, and only the turns tell
//     them apart. Its corners are also sought where the stroke turns most (besides the corner
//     search);
//   - a triangle's, quadrilateral's, polygon's or regular polygon's corners are fitted where the
//     hand turned: at each corner the stroke passes away from its ends it turns, between the same
//     chords, by at least 0.5 of the corner's turn, or it only lies in the shape's band (a
//     heart's lobes, a loop on a stick, a figure eight, a star whose points a pentagon cuts off,
//     an octagon in a regular pentagon's band). Model shapes' corners (rectangle, square,
//     diamond) may be drawn round one by one, but on the whole the stroke turns at them: the mean
//     share over their corners is at least 0.45 (a circle through them makes 0.25);
//   - a shape of k = 3..7 corners has every corner the hand drew: when the stroke turns sharply
//     at k + 1 places in the plane, each by at least 0.3 of a regular (k + 1)-gon's turn and
//     twice the stroke's median turn, it gives way to a polygon snap of more corners (a heptagon
//     lies within epsilon of a hexagon, a hexagon of a quadrilateral; a group's chain too); a
//     (regular) polygon is no snap when the stroke turns at k + 1 places by a regular k-gon's
//     whole turn (a star's outline);
//   - an arc must turn one way only (its net turning is most of its total turning; a brace or
//     an S turns both ways) and sweep less than a full turn.
// Among the plausible certified candidates the lowest rank wins,
//     rank = (bound + 2 rms) / epsilon + 0.15 * (free parameters),
// with rms the root-mean-square distance of the stroke to the clean shape (the mean error tells
// a sloppy circle from a sloppy square better than the worst error does): a square (4) before a
// rectangle or diamond (5) before a quadrilateral (8) before a polygon (2 per corner), a circle
// (3) before an ellipse (5), unless the richer shape fits clearly better. `alternatives` lists
// every other candidate with its certificate (and why it was rejected). Strokes with no plausible
// certified candidate are `freeform`.
//
// Dots. A stroke whose samples all sit at one position is a `dot` (never an error): its clean
// shape is that point, certified with bound 0 (the two paths coincide), in every entry
// (recognize, the live recognizer, the grouper, where a dot is never joined with other strokes).
//
// Limits (explicit, InvalidInput when exceeded): at least 1 sample,
// at most RecognizerConfig::max_samples samples, finite coordinates with |x|, |y| <= 1e9, and a
// configuration with finite, non-negative pen radius and tolerance, positive fractions and
// 0 <= thin_tolerance_fraction <= 0.25.
//
// Two entries. recognize(samples) sees the pen path only and certifies on the paths as above
// (Certificate::method "path"): a statement about the ink drawn with one pen radius. It builds
// no ink polygon. recognize(StrokeInput) takes the whole stroke: the samples, and optionally the
// ink polygon Q the engine computed (any radii, pressure included) and the deconstruction's
// skeleton P. With Q the snap is decided by the ink-level certificate (ink_certificate.hpp,
// method "ink"): the candidates are screened, ranked and checked for plausibility exactly as
// above with the path certificate (cheap), then the candidates that passed (certified and
// plausible) are certified again on the inks, best rank first, until one passes: it wins. Those
// that failed stay as alternatives whose certificate (method "ink", certified false) says why;
// passed candidates ranked after the winner keep their path certificate (method "path"). A
// candidate the path screening refused is not tried on the ink (its path bound or plausibility
// already failed; this keeps the pen-up cost to about one ink certificate per stroke). Epsilon
// follows the same rules, with StrokeInput::pen_radius as r when given. With P (a few vertices
// whose r-offset is within epsilon of Q), its vertices also seed the corners of the triangle and
// quadrilateral families: a seeded fit replaces the corner search's fit when its fit error is
// lower (P's largest outer ring reduced to 3 or 4 vertices). Measured on the $1 logs with P from
// deconstruct() at eps = r / 2: shape and non-shape rates unchanged, 4 of 1440 classes differ
// (tests/core/recognize/skeleton_seeds_test.cpp); it is kept because it does not hurt. Pass P
// from a deconstruction with eps < r: with eps >= r the answer is P = Q, whose vertices are not
// corners. The plausibility rules (straight_fraction) read the path bound in both entries.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "penshape/core/deconstruct.hpp" // InvalidInput
#include "penshape/core/ink.hpp"         // InkPolygon
#include "penshape/core/polygon_set.hpp" // PointD

namespace penshape {

enum class ShapeClass {
  kFreeform,
  kSegment,
  kPolyline, // open, 2..max_polyline_segments segments
  kTriangle,
  kQuadrilateral,
  kRectangle,
  kSquare,
  kDiamond,        // a rhombus (any orientation) whose angles are > 15 degrees from right ones
  kRegularPolygon, // 5, 6 or 8 equal sides and angles
  kCircle,
  kEllipse,
  kArc,         // an open circular arc
  kArrow,       // a shaft and a head of two barbs (group_recognize.hpp, "Arrows")
  kDoubleArrow, // a shaft with a head at both ends
  kDot,         // every sample at one position (a full stop, a tap): the point itself
  kPolygon      // any other closed polygon of 5..8 corners (hexagons, pentagons as drawn)
};

const char* to_string(ShapeClass c); // "freeform", "segment", ..., "regular_polygon", ...
std::optional<ShapeClass> shape_class_from_string(const std::string& name);

// One pen sample as the recognizer sees it: position in any unit (device units, px, mm) and a
// time in seconds (used only for ordering; may be 0).
struct StrokePoint {
  double x = 0.0;
  double y = 0.0;
  double t = 0.0;
};

struct RecognizerConfig {
  // Pen radius in the samples' unit; <= 0 means default_pen_radius_fraction * drawing size.
  double pen_radius = 0.0;
  // Tolerance epsilon in the samples' unit; <= 0 means the default rule below.
  double tolerance = 0.0;
  // Default pen radius relative to the drawing size (the bounding-box diagonal), used when the
  // caller knows no pen: 2.5% of a 10 cm drawing is a 2.5 mm pen, a felt tip or wide stylus.
  double default_pen_radius_fraction = 0.025;
  // Default epsilon = min(tolerance_size_fraction * size + tolerance_pen_radii * r,
  // max_tolerance_fraction * size) ("Tolerance epsilon" above). The hand's wobble grows with
  // the size of what it draws: the size term, derived from real strokes (recognize_bench
  // --derive-tolerance, leave-one-subject-out).
  double tolerance_size_fraction = 0.125;
  // ... plus the ink's own radius: the clean ink is drawn with r while a pressure pen's ink
  // varies by up to r along the stroke, so the ink certificate needs that much slack.
  double tolerance_pen_radii = 1.0;
  // ... bounded by this fraction of the size, so a wide pen on a small mark never snaps
  // coarsely (above it, unrelated gestures start to certify: same derivation).
  double max_tolerance_fraction = 0.135;
  // Straight open shapes (segment, polyline) must certify within this fraction of epsilon.
  double straight_fraction = 0.35;
  // Arcs: net turning / total turning at least this (1 = turns strictly one way).
  double arc_monotone_turning = 0.8;
  // Open polylines have at most this many segments (more is handwriting, not a shape).
  std::size_t max_polyline_segments = 3;
  // Dense strokes: the path is thinned within tau = thin_tolerance_fraction * epsilon before
  // fitting and certifying, and tau is added to the certified bound ("Dense strokes" above).
  // 1/50 costs 2% of the tolerance; measured on the $1 logs (as logged and at 1 kHz): 97.6% of
  // the shapes named right as unthinned, 1% non-shape snaps, 14 of 2880 classes differ from
  // unthinned (1/20 lost 3 of 540 shapes whose bound was within tau of epsilon). Limit:
  // 0 <= thin_tolerance_fraction <= 0.25; 0 turns thinning (and the segment grid) off.
  double thin_tolerance_fraction = 0.02;
  // Input limit.
  std::size_t max_samples = 100'000;
};

// The certificate: an upper bound on the Hausdorff distance between the clean shape's ink and
// the stroke's ink (same pen radius), and what it was computed with.
struct Certificate {
  bool certified = false;      // bound <= epsilon
  double bound = 0.0;          // >= H(clean ink, stroke ink), see the header comment
  double epsilon = 0.0;        // the tolerance it was checked against
  double pen_radius = 0.0;     // r used
  double sample_spacing = 0.0; // h of the sampling argument
  // "path": the bound is on H(stroke path, clean path) (this header's argument), which bounds
  // the inks when the stroke's ink is its path ⊕ one disk; "ink": the bound is on H(clean ink,
  // true stroke ink) from the ink polygon (ink_certificate.hpp), pressure-varying ink included.
  std::string method = "path";
};

struct ShapeParams {
  std::vector<PointD> vertices; // segment ends, polyline vertices, polygon corners (CCW or
                                // as drawn), empty for circle/ellipse
  PointD center;                // circle, ellipse, arc, polygons (centroid of the corners)
  double radius_x = 0.0;        // circle/arc radius, ellipse semi-axis along `rotation`
  double radius_y = 0.0;        // ellipse semi-axis across `rotation` (== radius_x for circles)
  double rotation = 0.0;        // radians: ellipse/rectangle/square/diamond orientation
  double start_angle = 0.0;     // arc: start and signed sweep, radians
  double sweep_angle = 0.0;
  double head_angle = 0.0; // arrows: mean angle between a barb and the shaft, radians
  // Arrows: the shaft is the circular arc from tail to tip whose midpoint lies this far to the
  // left of the chord tail -> tip (negative: to the right); 0 is a straight shaft.
  double shaft_bulge = 0.0;
  // Arrows: a bent shaft, the polyline tail -> shaft_bends[0] -> ... -> tip (interior vertices
  // from tail to tip, at most 2; group_recognize.hpp, "Arrows"). Empty for a straight or arc
  // shaft; a bent shaft is straight between its bends (shaft_bulge is then 0).
  std::vector<PointD> shaft_bends;
  // Arrows (kArrow) whose shaft stops short of the tip (a head drawn in its own stroke): the
  // shaft is tail -> shaft_bends -> shaft_end and the head (barb, tip, barb) stands apart, the
  // clean shape is these two pieces (shaft_bulge is then 0). Absent: the shaft runs to the tip.
  std::optional<PointD> shaft_end;
};

struct Candidate {
  ShapeClass shape = ShapeClass::kFreeform;
  ShapeParams params;
  std::vector<PointD> clean; // the clean shape as a path (closed shapes repeat the first
                             // point at the end; circles/ellipses densely sampled)
  Certificate certificate;
  std::string rejected; // why a certified candidate is not a snap (empty: plausible)
  double rms = 0.0;     // root-mean-square distance of the stroke to the clean path (ranking)
};

struct Recognition {
  ShapeClass shape = ShapeClass::kFreeform; // kFreeform when nothing certifies
  ShapeParams params;
  std::vector<PointD> clean; // empty for freeform; an arrow with a shaft_end: its shaft, then its
                             // head (the step between them is no part of it: clean_pieces)
  double rms = 0.0;          // of the winner, see Candidate::rms
  double confidence = 0.0;   // 1 - bound / (2 epsilon) of the winner (0.5..1), 0 freeform
  Certificate certificate;   // of the winner (certified == false for freeform; its method is
                             // "ink" whenever the ink polygon was given)
  std::vector<Candidate> alternatives; // the other candidates tried, best bound first
  double epsilon = 0.0;
  double pen_radius = 0.0;
};

// Throws InvalidInput (naming the problem) for bad input; see the limits above.
Recognition recognize(const std::vector<StrokePoint>& samples, const RecognizerConfig& config = {});

// The whole stroke, as the engine knows it (see "Two entries" above). The pointers are not
// owned and must stay valid during the call; null means "not given". The ink is given when
// `ink` or `ink_when_needed` is set.
struct StrokeInput {
  std::vector<StrokePoint> samples; // the pen path (as for recognize(samples))
  const InkPolygon* ink = nullptr;  // Q of these samples, in the samples' unit
  // Deconstruction's P (a YES answer's solution, same unit): corner seeds for polygons.
  const PolygonSet* skeleton = nullptr;
  // The clean ink's pen radius (with pressure: the radius the clean shape is drawn with, e.g.
  // the stroke's typical radius); <= 0 uses RecognizerConfig::pen_radius and its default rule.
  double pen_radius = 0.0;
  // Q while it is still being built (say on another thread, so that building Q overlaps fitting
  // the path): used only when `ink` is null. recognize() and StrokeGrouper::add() call it only
  // when a certificate reads Q (a candidate that snaps on the path is confirmed on the ink, or a
  // lone stroke's tidy-up), after the path is fitted; an answer that reads no Q (nothing snaps,
  // a dot, a union of strokes) never waits for it. When called, its errors are theirs (an
  // exception from it propagates; a stroke refused so is not added); when not, they are the
  // caller's. It must return Q of these samples (non-null), the same one on every call, valid
  // until the call that asked for it returns.
  std::function<const InkPolygon*()> ink_when_needed;
};

// The clean path as the pieces of the shape: one piece, or for an arrow whose shaft stops short of
// its tip (ShapeParams::shaft_end) the shaft (tail .. shaft_end) and the head (barb, tip, barb).
std::vector<std::vector<PointD>> clean_pieces(ShapeClass shape, const ShapeParams& params,
                                              const std::vector<PointD>& clean);

// Throws InvalidInput as recognize(samples) does, and for an empty ink polygon.
Recognition recognize(const StrokeInput& stroke, const RecognizerConfig& config = {});

// The tolerance and pen radius the recognizer uses for these samples (the rule above).
struct ToleranceChoice {
  double pen_radius = 0.0;
  double epsilon = 0.0;
  double size = 0.0; // bounding-box diagonal
};
ToleranceChoice choose_tolerance(const std::vector<StrokePoint>& samples,
                                 const RecognizerConfig& config);

} // namespace penshape
