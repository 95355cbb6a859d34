#pragma once
// Vector arithmetic on the public PointD, written once for core and its clients (snap, the
// annulus sweeps). Doubles: for proposals and drawing, never for a certified decision.
//
// Not included by polygon_set.hpp on purpose: a file that still defines these operators in its
// own namespace would see two equally good overloads through argument-dependent lookup.
#include <cmath>

#include "penshape/core/polygon_set.hpp"

namespace penshape {

inline PointD operator+(PointD a, PointD b) { return {a.x + b.x, a.y + b.y}; }
inline PointD operator-(PointD a, PointD b) { return {a.x - b.x, a.y - b.y}; }
inline PointD operator*(double s, PointD a) { return {s * a.x, s * a.y}; }
inline PointD operator*(PointD a, double s) { return {a.x * s, a.y * s}; }
inline double dot(PointD a, PointD b) { return a.x * b.x + a.y * b.y; }
inline double cross(PointD a, PointD b) { return a.x * b.y - a.y * b.x; }
inline double norm(PointD a) { return std::sqrt(dot(a, a)); }
inline double distance(PointD a, PointD b) { return norm(a - b); }

} // namespace penshape
