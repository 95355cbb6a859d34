#pragma once
// How the stroke traces a clean shape: the stroke's points taken in order along the shape's own
// path. A shape drawn once advances along its path one way; a letter, a note or a question mark
// that merely stays in a shape's band runs back over part of it (a stem drawn down and up again).
#include <vector>

#include "recognize/fitting/clean_shape.hpp"

namespace penshape::recognize_detail {

// The share of the shape's path length over which the stroke runs backwards: the stroke's points
// (in drawing order) are placed at their nearest point along `path` (closed when it ends where it
// starts: steps wrap around), and the steps against the net direction are summed. 0 for a shape
// traced one way; about 2 x stem / perimeter for a stem drawn down and up in a box's band.
double backtrack_share(const std::vector<PointD>& stroke, const std::vector<PointD>& path);

// The same for a closed shape drawn in several strokes, each taken in its own drawing order against
// its own net direction: where a closed shape's strokes overlap as they close it, the shortest
// chain of them may run one backwards (a circle drawn round once and a quarter, cut in four).
// The sum of their shares.
double backtrack_share(const std::vector<std::vector<PointD>>& strokes,
                       const std::vector<PointD>& path);

// Whether `path` ends where it starts (within rounding of its length: a sampled full curve).
bool closed_path(const std::vector<PointD>& path);

} // namespace penshape::recognize_detail
