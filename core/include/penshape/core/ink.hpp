#pragma once
// The ink polygon of a stroke: Q = stroke ⊕ pen disk, the region a wide-tip pen covers.
//
// Units: millimetres, in the tablet's axes (x to the right, y downwards as the device reports;
// a point (x, y) in device units is (x / x_resolution, y / y_resolution) mm; a resolution of 0
// (unknown) takes device units as millimetres).
//
// Construction: the stroke's samples, in order, form a polyline (one sample: a point), cut into
// chunks of kInkChunkSegments segments from its first sample (consecutive chunks share their end
// sample), each chunk simplified on its own (Douglas-Peucker on position plus radius, tolerance
// tau, keeping the chunk's ends) and turned into pieces on its own as below; Q is the one union
// of all chunks' pieces. Chunks let Q be built while the stroke is drawn (ink_builder.hpp) with
// the same result; each chunk's pieces go through the same roundings and unions as a whole
// stroke's would, so the bound below holds for them alike. Each segment sweeps the
// convex hull of the pen disks at its two ends; Q is the union of these hulls (Clipper, int64,
// non-zero fill; with one radius throughout, Clipper's round-joined offset of the open
// polyline, the same region with arcs of the same accuracy). So doubling back, self-crossings
// and loops (holes where a loop encloses area) come out right, and several strokes give several
// components. Three approximations, each bounded and added into InkPolygon::hausdorff_bound (a
// bound on the Hausdorff distance between Q and the exact swept region of the true disks):
//   1. the disk (or each round join/end) is a polygon inscribed in the circle with sagitta
//      <= max_error/2 (the k-gon: r_max·(1 - cos(π/k)); Clipper's arcs: 2.25 times its arc
//      tolerance, as it rounds the step count);
//   2. the simplification: error <= tau;
//   3. coordinates are rounded to a grid of 2^-m mm (Clipper's integers): at most four
//      roundings of half a grid diagonal (an offset stroke's input, offset vertices, the
//      offset's own union, the final union; a hull stroke has two), and each union's sweep
//      decides on x rounded to the grid: up to one grid unit per union (two beyond 2^50 grid
//      units), two unions for an offset stroke, one for hulls (core/src/ink/ink_union.hpp). The
//      grid is chosen so that (4·sqrt(2)/2 + 2·1)·grid <= max_error / 4.
// The sum is computed with outward rounding, plus 16 ulps of (extent + radius) for the double
// arithmetic that places the vertices and measures the simplification's distances, plus
// Clipper's own arithmetic in round joins and ends (it turns a unit vector step by step in
// doubles: 32 ulps of the radius per step, ink.cpp clipper_turning), plus, for each union,
// Clipper's double arithmetic in its intersection points and sweep: 192·2^-53 of the largest grid
// coordinate (and half a grid diagonal more beyond 2^52 grid units), derived from Clipper 6.4's
// source in core/src/ink/ink_union.hpp, which also says what that derivation assumes. Disks
// smaller than four grid units are drawn with four (the bound adds the difference): thinner
// pieces could be pinched away whole by the final union. Where a piece still has a corner
// sharper than a right angle, the final union's terms are multiplied by 1 / sin of that angle.
// max_error splits as 1/2 (disk), 1/4 (simplification), 1/4 (grid). The disk polygon may have at
// most 4096 vertices (a smaller max_error relative to the radius is InvalidInput). Q's coordinates
// are exact dyadic rationals (integers times the grid).
//
// Pressure → radius (when use_pressure and the tablet reports pressure, pressure_max > 0):
//   radius(p) = radius_mm · (min_fraction + (1 - min_fraction) · (p / pressure_max)^gamma),
// so a feather touch draws min_fraction of the full radius and full pressure the full radius;
// gamma < 1 makes light pressure count more. Otherwise every sample has radius_mm.
#include <cstddef>
#include <vector>

#include "penshape/core/polygon_set.hpp"
#include "penshape/types/stroke.hpp"

namespace penshape {

// Segments per chunk of a stroke (above).
inline constexpr std::size_t kInkChunkSegments = 64;

struct InkOptions {
  double radius_mm = 0.5;            // pen radius (at full pressure), > 0
  double max_error_mm = 0.0;         // bound on the total approximation error; 0: radius_mm / 50
  bool use_pressure = false;         // per-sample radius from pressure (see the curve above)
  double min_fraction = 0.25;        // radius fraction at zero pressure, in [0, 1]
  double gamma = 1.0;                // pressure exponent, > 0
  std::size_t max_samples = 100'000; // longer strokes are InvalidInput
  bool operator==(const InkOptions&) const = default;
};

// A sample in millimetres with its pen radius.
struct InkSample {
  double x = 0.0;
  double y = 0.0;
  double radius = 0.0;
};

struct InkPolygon {
  PolygonSet region;            // Q: valid (validate_region), outer rings ccw, holes cw
  double hausdorff_bound = 0.0; // H(Q, exact swept region) <= this (mm), <= max_error unless
                                // disks were widened or a piece has a sharp corner (above)
  std::size_t disk_vertices = 0;
  double grid = 0.0; // coordinate grid (mm), a power of two
};

// Samples of a stroke in millimetres with their radii (the curve above).
std::vector<InkSample> ink_samples(const Stroke& stroke, const InkOptions& options);

// Q for samples in millimetres. Throws InvalidInput on no samples, too many, non-finite values,
// a non-positive radius or error, or coordinates beyond 10^9 mm.
InkPolygon ink_polygon(const std::vector<InkSample>& samples, const InkOptions& options);

// Q of several strokes drawn with the same pen: the union of their ink (several components
// where they do not touch). max_samples limits the total.
InkPolygon ink_polygon(const std::vector<std::vector<InkSample>>& strokes,
                       const InkOptions& options);

// Q of a stroke: ink_polygon(ink_samples(stroke, options), options). Every sample counts, in
// order (the tip-up sample at the end too: it is where the pen left the surface).
InkPolygon ink_polygon(const Stroke& stroke, const InkOptions& options);

} // namespace penshape
