#pragma once
// Whether a stroke of a circle or ellipse drawn in pieces is a stretch of it, whatever it reads as
// alone (group_plausibility.hpp asks it of every piece of a round union): a hand's third of a
// circle wobbles into corners, a short piece comes out straight, yet each follows the shape.
#include <cstddef>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::recognize_detail {

// Whether piece `i` of `paths` (every stroke's distinct path) is a stretch of the circle or
// ellipse `shape` (the caller's to check: it is one), whatever it reads as alone. It runs along the
// shape's own path over it (the path between the points nearest the piece's ends, the way round
// that holds its middle; the piece's chord no longer than that path by more than kArcMinSagitta
// epsilon: a tick across the shape's line spans none of it); that path is as straight as the
// tolerance tells (it stands out from its chord by less than kArcMinSagitta epsilon, as an arc
// flatter than a segment's band: GroupRules::flat_round_pieces) or the piece stands out from its
// own chord on the same side by at least kMinBendShare as far (GroupRules::bent_round_pieces); and
// it meets the other pieces without corners wherever it meets one (an end of another within `join`,
// the chain's largest jump, going on turned by at most kMaxSmoothJoinTurn). A D's stem spans half
// the shape, straight where the shape bends, and meets its bowl at two corners.
bool follows_round_shape(const Recognition& shape, const std::vector<std::vector<PointD>>& paths,
                         std::size_t i, double join);

} // namespace penshape::recognize_detail
