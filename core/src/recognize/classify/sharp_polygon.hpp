#pragma once
// The sharp-polygon rule (recognize.hpp, "Classes"): a stroke that turns sharply at every corner
// of a polygon of 5..8 corners is that polygon, not the circle, ellipse or blunt shape of fewer
// corners whose band holds it too; a star's outline is no polygon. Shared by evaluate() and the
// live recognizer's preview, which weighs candidates fitted in different steps.
#include <string>
#include <vector>

#include "recognize/classify/classifier.hpp"

namespace penshape::recognize_detail {

// The turn at each corner of a regular polygon of k corners (radians).
double regular_turn(std::size_t k);

// Whether the stroke turns at every corner of a (regular) polygon of 5..8 corners as a drawn
// corner does (corner_sharpness.hpp): the evidence that it is no circle or ellipse.
bool sharp_polygon(const PreparedStroke& s, const Fit& f, const RuleThresholds& rules = {});
// Whether a snap gives way to a sharp polygon that fits nearly as tightly (fit_measure): a
// circle or ellipse, or a shape with corners the stroke does not turn sharply at (a square's band
// holds a hexagon too).
bool yields_to_sharp_polygon(const PreparedStroke& s, const Fit& f,
                             const RuleThresholds& rules = {});
// Takes the snap from every candidate that yields to a sharp polygon snap among `scored`.
void yield_to_sharp_polygon(const PreparedStroke& s, std::vector<Scored>& scored,
                            const RuleThresholds& rules);

// Why a polygon of k corners is a star's outline (empty when it is not): the stroke turns sharply
// at k + 1 places, each by at least a regular k-gon's turn.
std::string extra_corner_implausibility(const PreparedStroke& s, const Fit& f);
// A snap of k = 3..7 corners gives way to a polygon snap of more corners when the stroke turns
// sharply at k + 1 places in the plane, each by at least rules.min_missed_corner_turn of a
// regular (k + 1)-gon's turn (sharp_turn_corners): the hand drew a corner it leaves out. A
// group's chain too, though it steps at its joins where pieces meet off each other: polygons of
// 5..8 made from circles and cut at 1..2 corners, 59.0 -> 70.3% named with their corners
// (group_recognize_bench; real rectangles, triangles and diamonds in pieces unchanged).
void yield_to_more_corners(const PreparedStroke& s, std::vector<Scored>& scored,
                           const RuleThresholds& rules);

// Polygons of k corners from the corner search, and from where the hand turned most (the search
// may settle on a lumpy side's wobble): refined from the turns, through them, at them (fit.hpp);
// fits with a finite error only.
std::vector<Fit> polygon_fits(const PreparedStroke& s, std::size_t k);

} // namespace penshape::recognize_detail
