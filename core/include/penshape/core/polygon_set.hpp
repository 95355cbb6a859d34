#pragma once
// Polygonal regions with exact rational coordinates: the geometry contract's value type.
//
// A PolygonSet is a union of disjoint polygons, each an outer ring with holes. Coordinates are
// GMP rationals so every double converts exactly and every certified result keeps its exact
// vertices; to_double() is for display only. No CGAL here: this header is used everywhere.
#include <cstddef>
#include <vector>

#include "penshape/core/base.hpp" // Rational

namespace penshape {

struct ExactPoint {
  Rational x;
  Rational y;
  friend bool operator==(const ExactPoint&, const ExactPoint&) = default;
};

struct PointD {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const PointD&, const PointD&) = default;
};

// A closed ring: the last vertex connects back to the first (which is not repeated).
using Ring = std::vector<ExactPoint>;

struct PolygonWithHoles {
  Ring outer;              // counterclockwise
  std::vector<Ring> holes; // clockwise, inside outer, pairwise disjoint
};

struct PolygonSet {
  std::vector<PolygonWithHoles> polygons;

  [[nodiscard]] bool empty() const { return polygons.empty(); }
  [[nodiscard]] std::size_t vertex_count() const;
};

// Exact conversion: every finite double is a dyadic rational. Precondition: std::isfinite(v).
Rational exact(double v);
ExactPoint exact(PointD p);

// Nearest double (display only).
double to_double(const Rational& v);
PointD to_double(const ExactPoint& p);

// Twice the signed area (positive for counterclockwise), exactly.
Rational twice_signed_area(const Ring& ring);

// Area of the region: outer areas minus hole areas, exactly.
Rational area(const PolygonSet& set);

// +1 counterclockwise, -1 clockwise, 0 zero area; exact (doubles decide when clear).
int orientation_sign(const Ring& ring);

// Orients every outer ring counterclockwise and every hole clockwise.
void normalize_orientation(PolygonSet& set);
// True when normalize_orientation would change nothing.
bool has_normalized_orientation(const PolygonSet& set);

} // namespace penshape
