#pragma once
// Polygons made by the project for tests and benches that must run without the real corpora:
// country-like outlines with fractal coastlines, raster staircases, combs, spiky stars, regions
// with holes and islands, and thin features (a narrow bridge and a slit). Each is returned as
// the x-y text the polygon files use (polygon_io.hpp: `x y` a line, a blank line between rings,
// `#` header lines saying how it was made), so tests read it through the same parser as real
// files. A seed fixes every vertex; every outline is simple (no self-intersection) by
// construction, as the comments in polygon_gen.cpp argue.
#include <cstdint>
#include <string>
#include <vector>

namespace penshape::gen {

struct GenPolygon {
  std::string name; // e.g. "country_1881"
  std::string text; // x-y format
};

// A star-shaped coastline of `vertices` vertices around (0, 0), radius about `radius`: the
// radius follows fractal (1/f^roughness) noise over the angle, like a country's border.
GenPolygon country(std::uint64_t seed, int vertices, double radius, double roughness = 1.1);
// A staircase of `steps` random integer steps (a raster-traced outline), about `size` wide.
GenPolygon staircase(std::uint64_t seed, int steps, int size);
// A comb of `teeth` teeth of width `tooth`, gaps `gap`, depth `depth`, on a back 2 * tooth high.
GenPolygon comb(int teeth, double tooth, double gap, double depth);
// A star of `spikes` spikes between radii `inner` and `outer` (each jittered by the seed).
GenPolygon spikes(std::uint64_t seed, int spikes, double inner, double outer);
// A square of side `size` with `holes` square holes in a row, an island inside every other hole.
GenPolygon holes_and_islands(int holes, double size);
// Two blocks joined by a bridge `width` wide, and a slit `width` wide cut into one block.
GenPolygon thin_features(double size, double width);

// A YES instance with a known answer: P, a random convex polygon of `vertices` vertices on a
// circle of diameter `size`, and Q, its offset by `r` with every round corner replaced by chords
// whose vertices lie on the arc, so H(offset(P, r), Q) <= max_error (chord sagitta bound).
struct OffsetInstance {
  GenPolygon p;
  GenPolygon q;
};
OffsetInstance rounded_convex(std::uint64_t seed, int vertices, double size, double r,
                              double max_error);

// One of each, with the seed: what the bare-clone tests and benches iterate over.
std::vector<GenPolygon> polygon_suite(std::uint64_t seed);

} // namespace penshape::gen
