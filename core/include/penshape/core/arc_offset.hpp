#pragma once
// offset(P, r) with true circular arcs: what a renderer or a cutting machine wants.
//
// The boundary of offset(P, r) consists of line segments (edges of P moved out by r) and arcs of
// radius r around P's convex vertices. Rings are oriented with the region on the left (outer
// rings counterclockwise, holes clockwise), so every arc runs counterclockwise about its centre.
// Arc centres are P's vertices exactly (converted to doubles) and radii exactly r; the curve end
// points come from an int64 offset (Clipper) and carry the stated error: every boundary point
// lies within `max_error` of the exact offset's boundary.
#include <vector>

#include "penshape/core/polygon_set.hpp"

namespace penshape {

struct BoundaryCurve {
  enum class Kind { kSegment, kArc };
  Kind kind = Kind::kSegment;
  PointD start;
  PointD end;
  // Arcs only: centre and radius; the arc runs counterclockwise from start to end.
  PointD center;
  double radius = 0.0;
};

struct CurveRing {
  std::vector<BoundaryCurve> curves; // closed: each curve ends where the next starts
};

struct CurvedPolygon {
  CurveRing outer;
  std::vector<CurveRing> holes;
};

struct CurvedRegion {
  std::vector<CurvedPolygon> polygons;
  double max_error = 0.0; // bound on the distance of any boundary point to the exact boundary
};

// offset(P, r) for a valid region P (validate_region) and r > 0; max_error 0 means r / 1000.
// P may also hold curves, the degenerate solutions of simplification and of the convex path: an
// outer ring of zero area without holes (a point [a], a segment [a, b], a polyline walked there
// and back [a, p, b, p]) stands for the chain of its edges, whose offset has round ends.
// Throws InvalidInput on bad input (non-positive or non-finite r or error, invalid P, a curve
// with holes, sizes beyond the int64 grid).
CurvedRegion offset_with_arcs(const PolygonSet& p, double r, double max_error = 0.0);

} // namespace penshape
