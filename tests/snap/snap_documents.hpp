#pragma once
// Project-made documents for `penshape snap` on the cases real files showed (issue #29): pressure
// widths of 0 and -1, dots, closed subpaths, marked strokes drawn backwards, mixed styles,
// calligraphy of varying width, deep nesting, zip packages, gzip bombs, many pages. The strokes
// are synthetic hand-like lines (a deterministic wobble), so no outside data is needed.
#include <map>
#include <string>
#include <vector>

#include "penshape/core/polygon_set.hpp" // PointD

namespace penshape::test::docs {

// A hand-drawn-looking circle (n points, radius wobbling by 1%), drawn counterclockwise on screen.
std::vector<PointD> wobbly_circle(double cx, double cy, double r, int n = 64);
// A hand-drawn-looking straight stroke from a to b (n points, 0.3 units of wobble).
std::vector<PointD> wobbly_line(PointD a, PointD b, int n = 24);

// "x y x y ..." with the separator between a point's coordinates.
std::string coordinates(const std::vector<PointD>& pts, const char* within = " ");

// An SVG of 400 x 300 user units holding `body` (xmlns for inkscape and sodipodi declared, and
// an arrowhead marker #arrow in <defs>).
std::string svg_document(const std::string& body);

// A .xopp XML document: one 400 x 300 pt page per entry, each one layer holding the entry.
std::string xopp_document(const std::vector<std::string>& layers);
// <stroke tool= color= width=>points</stroke>.
std::string xopp_stroke(const std::vector<PointD>& pts, const std::string& width,
                        const std::string& color = "#000000ff");

// A zip of the entries (name -> bytes, the first stored uncompressed as Xournal++'s mimetype is),
// and a zip's entries read back.
std::string zip_package(const std::vector<std::pair<std::string, std::string>>& entries);
std::map<std::string, std::string> zip_entries(const std::string& zip);

// gzip of `bytes` zero bytes, made in slices (a compression bomb of ~1/1000 its size).
std::string gzip_of_zeros(std::size_t bytes);

} // namespace penshape::test::docs
