#pragma once
// The clean shape runs the way the drawer drew: an open shape (segment, polyline, arc, double
// arrow) whose start lies nearer the ink's end than its start is reversed, so markers
// (marker-start, marker-end) and arrowheads stay at the ends they were drawn at. A single arrow's
// tip stays its head, where the drawer put the barbs; one drawn from its head to its tail is
// written end to start (the head first, then the shaft to the tail), so the written path runs as
// the pen did and its markers sit at the ends the drawer started and ended at. Closed shapes have
// no ends and stay as they are.
#include "penshape/core/recognize.hpp"

namespace penshape::snap {

// `start` is the first ink point drawn, `end` the last. True when the shape is to be written end
// to start: a single arrow drawn head first.
bool orient_like_drawn(Recognition& r, PointD start, PointD end);

} // namespace penshape::snap
