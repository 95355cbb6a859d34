#pragma once
// SVG path data (the `d` attribute) and point lists (`points`) as polylines: every command of
// SVG 1.1 (M L H V C S Q T A Z, absolute and relative, implicit repeats), with curves and
// elliptical arcs flattened within a given distance. The one tested place where SVG geometry is
// read (transform.hpp holds the transforms).
#include <cstddef>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "penshape/core/polygon_set.hpp" // PointD

namespace penshape::snap {

struct Subpath {
  std::vector<PointD> points; // the flattened path; a closed subpath does not repeat its start
  bool closed = false;
};

struct PathDataError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// `flatness` > 0: every curve point lies within this distance of the polyline (and the
// polyline's vertices lie on the curve). Throws PathDataError naming the offset and command.
std::vector<Subpath> parse_path_data(std::string_view d, double flatness);

// The `points` attribute of polyline/polygon: pairs of numbers. Throws PathDataError on an odd
// count or a bad number.
std::vector<PointD> parse_point_list(std::string_view points);

// The centre parametrisation of an SVG arc from p0 to p1 (SVG 1.1 implementation notes F.6.5,
// radii scaled up as F.6.6 says when too small): points along it, p1 included, p0 excluded.
std::vector<PointD> flatten_arc(PointD p0, double rx, double ry, double x_axis_rotation_deg,
                                bool large_arc, bool sweep, PointD p1, double flatness);

} // namespace penshape::snap
