#pragma once
// The ideal paths the stroke generator's hand follows, before the pen model (pen_model.hpp) adds
// its imperfections: closed outlines with an open or overshot end, arcs, zigzags, spirals,
// scribbles and cursive handwriting. Internal to the stroke generator.
#include <vector>

#include "pen_model.hpp"
#include "rng.hpp"

namespace penshape::gen {

// The vertices of a closed polygon walked from vertex `start`, ending `gap` short of the start
// (gap < 0: overshooting past it along the first edge by -gap). Corners not yet rounded.
std::vector<Pt> closed_outline(const std::vector<Pt>& vertices, std::size_t start, double gap);

// An ellipse (semi-axes a, b, rotated by `rotation`) swept from angle `from` by `sweep` radians
// (negative: clockwise).
std::vector<Pt> elliptic_arc(Pt centre, double a, double b, double rotation, double from,
                             double sweep);

// An Archimedean spiral from the centre out, `turns` turns to radius `radius`.
std::vector<Pt> spiral(Pt centre, double radius, double turns, bool clockwise);

// A smooth curve through `count` random points in a box of this size: a scribble.
std::vector<Pt> scribble(Pt centre, double size, int count, Rng& rng);

// A word of `letters` cursive lowercase letters, x-height `height`, starting at `origin` on the
// baseline, joined as one stroke the way a hand writes it.
std::vector<Pt> cursive_word(Pt origin, double height, int letters, Rng& rng);

// A smooth curve through the given points (centripetal Catmull-Rom, `per_span` points a span).
std::vector<Pt> smooth_through(const std::vector<Pt>& points, int per_span);

} // namespace penshape::gen
