#pragma once
// D̄_{a,b}: a convex polygon with rational vertices whose boundary lies in the annulus between
// the circles of radius a and b around the origin (deconstructing-approximate-offsets, Section 3,
// Lemmas 14-15). Vertices lie exactly on the circle of radius b (the rational parametrisation
// Q_t = (b(1-t²)/(1+t²), 2bt/(1+t²)), t = i/z, mirrored into the four quadrants), so
//   D_a ⊆ D̄_{a,b} ⊆ D_b.
// Offsets by D̄_{a,b} therefore lie between the exact offsets by radius a and radius b.
#include <cstddef>

#include "penshape/core/polygon_set.hpp"

namespace penshape {

// The smallest z with chord bound 2b/z <= 2·sqrt(b² - a²), i.e. z >= b / sqrt(b² - a²); the
// polygon then has 4z vertices. Precondition: 0 <= a < b.
std::size_t disk_approximation_z(const Rational& a, const Rational& b);

// D̄_{a,b}, counterclockwise, 4z vertices starting at (b, 0). Throws InvalidInput (from
// deconstruct.hpp) when a < 0, b <= a, or 4z > max_vertices (the message states the bound).
Ring disk_approximation(const Rational& a, const Rational& b, std::size_t max_vertices);

// Exact check of the two inclusions D_a ⊆ polygon ⊆ D_b for a convex counterclockwise ring:
// every vertex within distance b of the origin and every edge's line at distance >= a.
bool is_disk_approximation(const Ring& ring, const Rational& a, const Rational& b);

} // namespace penshape
