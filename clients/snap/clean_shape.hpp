#pragma once
// The clean shape of a recognition in the forms the writers need: a polyline fine enough to stay
// within the certificate (for formats without curves), and the tag-independent numbers.
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::snap {

// The clean path as points (closed shapes repeat their first point at the end). Circles,
// ellipses and arcs are sampled so finely that the chords stay within
// min(epsilon - bound, epsilon / 20, pen radius / 10) of the true curve: the polyline's ink is then
// within the tolerance of the stroke's ink, as the certificate says of the curve.
// An arrow whose shaft stops short of its tip (ShapeParams::shaft_end) cannot be one line: use
// clean_lines.
std::vector<PointD> clean_polyline(const Recognition& r);

// The clean shape as lines to draw: clean_polyline's one line, or the two pieces (shaft, head)
// of an arrow whose shaft stops short of its tip.
std::vector<std::vector<PointD>> clean_lines(const Recognition& r);

// An arrow's pieces as polylines: the shaft (tail -> shaft bends -> tip), the head (barb 1 ->
// tip -> barb 2), and a double arrow's tail head (barb 3 -> tail -> barb 4). A curved shaft: the
// recognizer's clean path as one piece when it is given (what was certified), else the arc
// sampled as clean_polyline samples arcs. clean_polyline joins the pieces into one line.
std::vector<std::vector<PointD>> arrow_pieces(const Recognition& r);

// Whether the recognizer's answer is a snap: a certified, non-freeform shape with the geometry of
// its class (two segment ends, three or more polygon corners, positive radii).
bool is_snap(const Recognition& r);

} // namespace penshape::snap
