#pragma once
// The integer grid the fast engine computes on: grid point (X, Y) stands for the exact rational
// ((X + tx) / 2^k, (Y + ty) / 2^k). The scale puts about 2^10 grid units into the precision
// delta, so rounding a vertex to the grid (at most sqrt(2)/2 units, see kInputRounding) is tiny
// against every margin the engine keeps, and results convert back to exact rationals.
#include <cstdint>

#include "certified.hpp"
#include "int_geometry.hpp"
#include "penshape/core/deconstruct.hpp"

namespace penshape::fast {

// Largest |grid coordinate| anywhere in the computation (Clipper's fast 64-bit range is 2^30;
// offsets stay inside the box enlarged by r + eps + 2 delta, which the frame includes).
inline constexpr double kMaxGridCoordinate = 1073741823.0; // 2^30 - 1
// Upper bound on the distance between an input vertex and its grid point: sqrt(2)/2 < 0.75
// (0.75² = 0.5625 > 1/2, exactly).
inline constexpr double kInputRounding = 0.75;

class GridFrame {
 public:
  // Chooses the scale for q and the parameters; throws InvalidInput when the coordinate
  // extent is more than 2^24 times delta (the grid would need more than 2^30 units).
  GridFrame(const PolygonSet& q, const DeconstructParams& params);

  // Length in grid units (rounded to double: relative error 2^-53).
  [[nodiscard]] double units(const Rational& length) const;
  // Length in grid units as doubles that enclose the exact value (CGAL::to_interval).
  [[nodiscard]] Bounds bounds(const Rational& length) const;

  // q rounded to the grid, each ring with the region on its left (outer CCW, holes CW).
  [[nodiscard]] IRings round(const PolygonSet& q) const;
  [[nodiscard]] IPt round(const ExactPoint& p) const;

  // Exact rational polygon set of integer rings given as outers with their holes.
  [[nodiscard]] ExactPoint exact(IPt p) const;

  [[nodiscard]] int scale_exponent() const { return k_; }

 private:
  int k_ = 0;
  mpz_class tx_, ty_;
};

} // namespace penshape::fast
