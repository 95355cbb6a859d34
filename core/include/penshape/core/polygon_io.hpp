#pragma once
// Reading polygonal regions from text, exactly (decimal digits become exact rationals; no
// double rounding on the way in).
//
// x-y format (../shared/data/polygons): one vertex `x y` per line, whitespace separated.
// Lines whose first non-blank character is `#` are comments. A blank line ends a ring, so a
// file may hold several rings:
//
//     # a square with a square hole, and an island inside the hole
//     0 0
//     10 0
//     10 10
//     0 10
//
//     2 2
//     2 8
//     8 8
//     8 2
//
//     4 4
//     6 4
//     6 6
//     4 6
//
// A ring's role follows from nesting, not from the order or orientation of its vertices: a
// ring inside an even number of other rings is an outer ring, one inside an odd number is a hole
// of the smallest ring around it. A closing repeat of the first vertex is dropped.
//
// WKT: `POLYGON ((x y, ...), (hole), ...)`, `MULTIPOLYGON (((...)), ((...)))`, case-insensitive;
// the first ring of each polygon is its outer ring; closing repeats are dropped. `EMPTY` gives an
// empty set. Z/M coordinates are rejected.
//
// Numbers: `[+-]digits[.digits][(e|E)[+-]digits]` or `p/q`, read exactly; the exponent is
// limited to ±400 (a decimal beyond that range is an error rather than a giant rational).
//
// Parsing does not validate the geometry: call validate_region (deconstruct.hpp) for that.
// Errors are ParseError with the 1-based line number in the message ("line 7: ...").
#include <cstddef>
#include <string>
#include <string_view>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_set.hpp"

namespace penshape {

struct ParseError : InvalidInput {
  ParseError(std::size_t line_number, const std::string& what)
      : InvalidInput("line " + std::to_string(line_number) + ": " + what), line(line_number) {}
  std::size_t line;
};

// An exact rational from decimal or p/q text; throws InvalidInput (not a ParseError: there is no
// line) naming the text.
Rational parse_rational(std::string_view text);

PolygonSet read_xy(std::string_view text);
PolygonSet read_wkt(std::string_view text);
// WKT when the first token outside comments is POLYGON or MULTIPOLYGON, x-y otherwise.
PolygonSet read_polygon_text(std::string_view text);

// WKT text of a set, exactly: a coordinate whose decimal expansion terminates (denominator
// 2^a·5^b, e.g. every double) prints as that decimal, any other as p/q (read_wkt reads both;
// other WKT readers only the former).
std::string to_wkt(const PolygonSet& set);

} // namespace penshape
