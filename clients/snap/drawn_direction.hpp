#pragma once
// The clean shape runs the way the drawer drew: an open shape (segment, polyline, arc, double
// arrow) whose start lies nearer the ink's end than its start is reversed, so markers
// (marker-start, marker-end) and arrowheads stay at the ends they were drawn at. A single arrow's
// tip is its head, as the recognizer found it; closed shapes have no ends and stay as they are.
#include "penshape/core/recognize.hpp"

namespace penshape::snap {

// `start` is the first ink point drawn, `end` the last.
void orient_like_drawn(Recognition& r, PointD start, PointD end);

} // namespace penshape::snap
