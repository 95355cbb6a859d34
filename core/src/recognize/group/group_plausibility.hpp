#pragma once
// Whether a union of several strokes that certifies as a shape is drawn the way people draw that
// shape in pieces (group_recognize.hpp, "Grouping"): the grouper keeps a union only when it is.
#include <span>
#include <string>

#include "penshape/core/group_recognize.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {

// Why the strokes are not a drawing of `r` in pieces (empty when they are, and for one stroke).
// A shape other than an arrow is its pieces drawn one after the other: the strokes chain end to
// end, every pen-up jump of the chain within 2 r + the epsilon of the largest stroke alone.
// Strokes that meet at a junction (a T, an H, the bar of an A) or a row of dashes are no
// polyline, polygon or segment even when the union's band covers them. And no stroke alone is
// of the other kind: no circle or ellipse in a straight-sided shape, and in a round one (circle,
// ellipse, arc) every piece an arc (alone, or bowed: an arc of the shape fits it, though the
// piece alone reads as a polyline or freeform) or, in a circle or ellipse, a piece over which the
// shape's own path is straight within epsilon / 2 and that meets the others without corners; a
// piece no larger than epsilon is any shape's. An arc alone may be a side and a rounded corner.
// Besides (GroupRules): an open polyline is never a group; two strokes that start at one point
// and leave it each its own way are limbs, no segment; no stroke of a straight-sided closed
// shape is a curve (the bowl of a D or a P); no two strokes of a closed shape cross each other
// away from their ends (a stick figure, a crossed circle); an arrow is drawn in at most as many
// strokes as it has straight parts (a shaft and two or four barbs), none of them a circle or an
// ellipse alone (a half note's head, a null sign's ring).
std::string group_implausibility(const Recognition& r, std::span<const StrokeInput> strokes,
                                 const RecognizerConfig& config);

// The rules above that were added with measured held-out figures, each switchable so that
// group_recognize_bench and the tests can show what one rule does. All on by default; the library
// never changes them (set them before recognizing, from one thread).
struct GroupRules {
  bool no_open_polylines = true;  // an open polyline in pieces stays apart
  bool no_curved_sides = true;    // a curve is no pair of straight sides
  bool no_crossing_pieces = true; // the pieces of an outline do not cross in their middles
  bool no_limbs_as_a_line = true; // two strokes leaving one point are no segment in pieces
  // The least turn at a corner inside one stroke, as a share of the shape's (no_curved_sides).
  double min_corner_turn_share = kMinCornerTurnShare;
  bool no_continued_tips = true; // no recent stroke leaves an arrow's tip forward (arrow_tip.hpp)
  // The half-angle of the cone around the shaft's direction a continuation stays in.
  double max_continuation_angle = kMaxContinuationAngle;
  bool arrow_when_refused = true; // a refused winner gives way to the union's arrow (keep_union)
  // A refused round winner (a circle, an ellipse, an arc) gives way to the union's best
  // straight-sided closed shape (keep_union).
  bool outline_when_round_refused = true;
  bool a_stroke_per_arrow_part = true; // an arrow has at most a stroke per shaft and barb
  bool no_round_arrow_pieces = true;   // no stroke of an arrow is a circle or ellipse alone
  // A round shape's piece that is no arc alone may be one an arc of it fits (bowed,
  // kMaxBowedCentreOff).
  bool bowed_round_pieces = true;
  // A circle's or ellipse's piece over which the shape's own path is as straight as the tolerance
  // tells, meeting the others without corners, may be any shape (round_pieces.hpp: a short piece
  // of a circle drawn straight; a D's stem meets its bowl at corners).
  bool flat_round_pieces = true;
  // A circle's or ellipse's piece that bends the way the shape does over it, at least
  // kMinBendShare as far from its chord, may be any shape (round_pieces.hpp).
  bool bent_round_pieces = true;
  // Two strokes of an outline that cross where one runs on along the other to its end (farther
  // than they may be apart, within kOverlapAlongside epsilon) overlap there: no crossing.
  bool overlaps_are_no_crossings = true;
  // Two strokes this many epsilons farther apart than touching are still tried together, and
  // kept only as an arrow (a shaft stroke that stops short of its head; apart_join; 0: never).
  double apart_join = kApartJoin;
};
GroupRules& group_rules();

// How much farther apart than touching (2 r + epsilon) a union of `strokes` strokes may be and
// still be tried: only two strokes, by GroupRules::apart_join epsilons (0 otherwise). A shaft
// drawn in its own stroke may stop short of its head's tip by up to kMaxGapBarb barbs, which the
// touch test alone would never try.
double apart_join(std::size_t strokes, double epsilon);
// Whether two strokes that do not touch may be kept as `r`: an arrow (its shaft stroke stops
// short of the head: a shaft_end, or a gap the tolerance covers). Every other shape drawn in
// pieces touches.
bool kept_apart(const Recognition& r);

struct UnionRecognition;
// Whether the grouper keeps the union `u` of `strokes` as one group: its winner is drawn as its
// shape is in pieces (group_implausibility) and, for an arrow, no stroke of `others` (the recent
// strokes outside the union) leaves its tip forward (tip_continued). A winner refused gives way
// to the union's best certified, plausible arrow (read_as_arrow) when that one passes, and a
// refused round winner (a round shape with a straight stroke among its pieces) to the union's best
// straight-sided closed shape (a polygon whose lumps a circle's band covers): `u` then holds it.
bool keep_union(UnionRecognition& u, std::span<const StrokeInput> strokes,
                std::span<const StrokeInput* const> others, const RecognizerConfig& config);

} // namespace penshape::recognize_detail
