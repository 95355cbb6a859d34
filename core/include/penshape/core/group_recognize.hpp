#pragma once
// Recognition of shapes drawn in several strokes (a rectangle as 4 sides or two L's, a triangle as
// 2-3 strokes, an arrow as a shaft and a head), arrows, and certified tidy-up. Built on the
// single-stroke recognizer (recognize.hpp) and certified with the same criterion: a group snaps
// only when the clean shape's ink is within Hausdorff distance epsilon of the UNION of the
// strokes' inks. No CGAL, no I/O, no threads: the daemon, the CLI and other clients use it as is.
//
// Grouping (StrokeGrouper). Strokes arrive in drawing order. Each finished stroke is first
// recognized alone; then it is tried together with recent groups (a group is the set of strokes
// one current answer covers; a lone stroke is a group of one):
//   - recent: the pause between the group's last pen-up and the new stroke's first sample is at
//     most GroupingConfig::max_pause_seconds (StrokePoint::t, seconds);
//   - small: the group and the new stroke hold at most GroupingConfig::max_strokes strokes;
//   - touching: the strokes, new one included, form a connected graph in which two strokes are
//     joined when their inks touch or nearly touch: their pen paths come within 2 r + epsilon
//     (each ink is its path widened by the pen radius r; epsilon as for the union, below).
// Every union of whole recent groups that passes these rules (at most 2^(max_strokes-1) unions)
// is recognized as one drawing; among the unions that snap (certified and plausible), the one
// covering the most strokes wins (ties: the lower rank). It replaces the groups it absorbed: the
// update names them as superseded. When no union snaps, the new stroke stands alone and the
// earlier answers are unchanged. Groups are only ever merged whole, so a finished shape is never
// torn apart, and two shapes whose union does not certify as one stay two shapes.
//
// Recognizing a union. epsilon and r follow recognize.hpp's rule on the union's bounding box. The
// strokes are chained (orders and directions minimising the pen-up jumps between the pieces)
// into one path that the single-stroke fitters and plausibility rules read as if it were one
// stroke; every candidate that passes is then certified on the union itself: with A the union of
// the strokes' (thinned) paths and B the clean path, the sampling bound of recognize.hpp runs over
// every piece of A (the jumps between pieces are NOT part of A) and d(b, A) is the distance to the
// nearest piece. The certificate's method is "path" (union of paths, one pen radius). A lone
// stroke is recognized by recognize(StrokeInput) unchanged (its ink certificate included when
// the ink is given), and arrows are tried besides. Several strokes make a closed shape (polygon,
// circle, ellipse) only when it is at least 2 epsilon wide: narrower, its whole inside lies
// within epsilon of its outline, so any strokes side by side would pass for it.
//
// Arrows (ShapeClass::kArrow, kDoubleArrow). A shaft from tail to tip and a head of two barbs
// from the tip, drawn in any strokes: one stroke (tail, tip, barb, back to the tip, other barb),
// a shaft and a "V", or a shaft and two barbs. A double arrow has a head at both ends. The shaft
// is a segment; else, where that does not fit within 0.6 epsilon, a circular arc (shaft_bulge)
// or a polyline with 1 or 2 bends (shaft_bends), whichever certifies: a straight or curved
// shaft that is a snap wins over any bent one (the tidier shape). The head is sought against
// the chord tail -> tip and against the shaft's own end: at each place a stroke ends or turns
// back (by more than 100 degrees), the stroke followed from there is taken as the shaft (the
// direction back along it to its first point 15% of it away), the barbs are the points off it,
// each ending where a stroke ends or turns back, and its middle's offset and Douglas-Peucker
// corners seed the curved and bent shafts (only for a shaft that reaches its tip 15 degrees or
// more off its chord: an arc or an elbow arrow, whose barbs can both lie on one side of it; only
// in a drawing that ends or turns back in at most 8 places, and each seed polished only when
// within 2 epsilon of the drawing: writing is not searched through).
// ShapeParams: vertices = {tail, tip, barb 1, barb 2} (+ {tail barb 1, tail barb 2} for a double
// arrow), rotation = direction of tail -> tip, head_angle = mean angle between a barb and the
// shaft at the tip (its last piece when bent), shaft_bulge, shaft_bends. The clean path is
// tail -> [shaft] -> tip -> barb 1 -> tip -> barb 2 (a set: the retrace is harmless for the
// Hausdorff distance). Plausible only when the certificate's bound is at most 0.6 epsilon, each
// barb is at least epsilon and at most 0.8 shaft lengths (along the shaft) long, the barbs lie on
// opposite sides of the shaft, each barb makes an angle of 10..80 degrees with the shaft's end
// piece, and the strokes are at most 1.6 times as long as the clean arrow; a bent shaft's bends
// each stand out from their neighbours' chord by epsilon / 2 or more, the shaft turns by at most
// 100 degrees at each, its end pieces lie within 25 degrees of their heads' axes (the bisector
// of the barbs), and each barb's end leaves the end piece's line by epsilon / 2 or more. Arrows
// rank with 8 (double: 12) free parameters, one more for a curved shaft, two more per bend.
// A shaft stroke may stop short of its head's tip (two strokes: a shaft, a head): the arrow is
// then two pieces, the shaft tail -> [bends] -> shaft_end (ShapeParams::shaft_end, seeded at the
// shaft stroke's end nearest the tip) and the head barb 1 -> tip -> barb 2, certified as that
// union (the gap is no part of it), with two more free parameters. Plausible only with the head
// drawn apart, the gap at most 1.3 mean barbs long and aimed at the tip (within 12 degrees of the
// shaft's direction, or the tip within epsilon / 2 of the shaft's line), and only when no arrow
// whose shaft runs to its tip is a snap. Two strokes up to 2 epsilon farther apart than touching
// are tried together for it, and kept together only as an arrow.
// Arrows are fitted, certified and judged within 0.925 epsilon (the rules above read epsilon as
// that): 12.5% of the size where the default epsilon is 13.5%, the fraction the arrow rules were
// measured at (the default tolerance is derived on single strokes; a looser band lets a brace or
// a half note pass for an arrow). A head is sought and judged at that scale, which follows the
// whole drawing (about an eighth of it): a long shaft's small head, barbs shorter than it, is no
// head there. When no arrow is a snap, arrows with a straight shaft are sought again at half of
// it, where the whole arrow must certify (so within epsilon) and pass every rule at that scale
// (barbs 7.5% of a 300 or 600 unit shaft make an arrow there). Its rank is taken at epsilon, as
// every other candidate's.
//
// Tidy-up (TidyConfig). The winner is then made more regular, one constraint at a time, each kept
// only when the result is still certified on the same strokes (else that constraint is skipped):
//   "circle"       an ellipse with semi-axes within 20% of each other becomes a circle;
//   "right_angles" a quadrilateral whose corners are within 10 degrees of right becomes a
//                  rectangle; an open polyline's corners within 10 degrees of right become right;
//   "equal_sides"  a rectangle whose sides differ by < 15% becomes a square; a triangle whose
//                  sides differ by < 15% becomes equilateral;
//   "axis"         the shape is turned about its centre so that its longest edge (a segment, an
//                  arrow's shaft, an ellipse's axis) lies exactly along an axis or a 45-degree
//                  diagonal, when within 10 degrees of it;
//   "parallel"     else, turned so its longest edge is parallel to an edge of a recent shape
//                  (the answers of the previous max_strokes groups) within 6 degrees;
//   "connection"   an open shape's end (segment, polyline, arrow tail or tip) within epsilon of a
//                  vertex of a recent shape moves onto it, else within epsilon of its outline
//                  moves onto the nearest point of it.
// GroupedShape::tidy lists the constraints applied, in this order.
#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape {

// Which tidy-up constraints may be tried (each is still applied only when certified).
struct TidyConfig {
  bool circle = true;
  bool right_angles = true;
  bool equal_sides = true;
  bool axis = true;
  bool parallel = true;
  bool connection = true;
};

struct GroupingConfig {
  // Grouping on (false: every stroke is recognized alone, arrows and tidy-up still apply).
  bool enabled = true;
  // At most this many strokes in one group (2..8). 4: a rectangle drawn side by side.
  std::size_t max_strokes = 4;
  // A stroke may join a group whose last stroke ended at most this long (seconds) before it
  // started. 2 s: drawing the next side of a shape takes well under a second; a pause of several
  // seconds means a new drawing.
  double max_pause_seconds = 2.0;
  TidyConfig tidy;
};

// One answer: a shape (or freeform) covering one or more strokes.
struct GroupedShape {
  std::size_t id = 0;               // unique within one StrokeGrouper (or one recognize_strokes)
  Recognition recognition;          // certified on the union of the strokes (see above)
  std::vector<std::size_t> strokes; // indices of the strokes it covers, ascending
  std::vector<std::string> tidy;    // constraints applied: "axis", "right_angles", ...
};

// What adding one stroke changed.
struct GroupUpdate {
  GroupedShape shape;                        // the answer that now covers the new stroke
  std::vector<std::size_t> superseded;       // ids of earlier answers it replaces (absorbed)
  std::vector<std::size_t> replaced_strokes; // strokes whose ink the shape replaces (= strokes)
};

// Per-tablet grouping state. Not thread-safe: one grouper per tablet (or per page).
class StrokeGrouper {
 public:
  explicit StrokeGrouper(GroupingConfig grouping = {}, RecognizerConfig recognizer = {});

  // Adds the next stroke in drawing order (its index is the number of strokes added before).
  // stroke.ink and stroke.skeleton need only stay valid during the call; stroke.ink_when_needed
  // is called after the unions with recent groups are tried (none of them needs the ink). Throws
  // InvalidInput as recognize() does; a refused stroke is not added.
  GroupUpdate add(const StrokeInput& stroke);

  // The current answers (superseded ones removed), ordered by their first stroke.
  [[nodiscard]] std::vector<GroupedShape> shapes() const;
  // Strokes added so far (the next stroke's index), forgotten ones included.
  [[nodiscard]] std::size_t stroke_count() const { return added_; }

  // Forgets what no later stroke can reach, so that a long session's memory stays bounded: the
  // samples of every stroke except those of the most recent groups a stroke may still join
  // (within max_pause_seconds, fewer than max_strokes strokes, at most 6 of them: the groups
  // add() tries), and every answer except those and the recent shapes tidy-up refers to (the
  // last max_strokes + 6 that snapped). Called after each add(), the later answers are the same
  // as without it. Indices and ids keep counting; shapes() then lists the kept answers only.
  void forget_unreachable();
  // Strokes whose samples are kept (those that may still join a group): after
  // forget_unreachable() at most 6 * (max_strokes - 1).
  [[nodiscard]] std::size_t retained_stroke_count() const { return strokes_.size(); }
  // The index of the oldest stroke whose samples are kept (stroke_count() when none is).
  [[nodiscard]] std::size_t oldest_retained_stroke() const {
    return strokes_.empty() ? added_ : strokes_.begin()->first;
  }

  // Forgets every stroke (a new page); ids keep increasing.
  void clear();

 private:
  struct Entry {
    GroupedShape shape;
    double end_time = 0.0; // last sample's t of its latest stroke
    bool joinable = true;  // false once too old to grow: its strokes' samples were dropped
  };
  GroupingConfig grouping_;
  RecognizerConfig recognizer_;
  // Samples and pen radius only (ink pointers dropped); strokes whose group can no longer grow
  // (older than max_pause_seconds) are dropped, so memory follows the window.
  std::map<std::size_t, StrokeInput> strokes_; // by stroke index, the strokes that may join
  // What unions test for touching, for each stroke in strokes_: its touch path (thinned once)
  // and its gaps to the strokes before it (each measured once, by the earlier stroke's index).
  struct Touch {
    std::vector<PointD> path;
    double slack = 0.0;
    std::map<std::size_t, double> gaps;
    PointD lo, hi; // the samples' bounding box: a union's tolerance without its samples
  };
  std::map<std::size_t, Touch> touches_; // by stroke index, beside strokes_
  void forget_stroke(std::size_t index); // from strokes_ and touches_
  std::size_t added_ = 0;                // strokes added (the next stroke's index)
  std::vector<Entry> groups_;            // current answers
  std::size_t next_id_ = 0;
};

// All strokes at once, in drawing order: the answers StrokeGrouper gives after the last stroke.
// Every stroke is covered by exactly one answer (freeform answers included).
std::vector<GroupedShape> recognize_strokes(std::span<const StrokeInput> strokes,
                                            const GroupingConfig& grouping = {},
                                            const RecognizerConfig& recognizer = {});

// One drawing made of several strokes, recognized as a whole (no grouping decision, no tidy-up):
// the union rule above. One stroke: recognize(stroke) and arrows. Throws InvalidInput for bad
// strokes (as recognize()) or none.
Recognition recognize_union(std::span<const StrokeInput> strokes,
                            const RecognizerConfig& config = {});

} // namespace penshape
