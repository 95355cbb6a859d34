#pragma once
// The integer grid the fast engine computes on: grid point (X, Y) stands for the exact rational
// ((X + tx) / 2^k, (Y + ty) / 2^k). The scale puts about 2^10 grid units into the precision
// delta, so rounding a vertex to the grid (at most sqrt(2)/2 units, see kInputRounding) is tiny
// against every margin the engine keeps, and results convert back to exact rationals.
#include <cstddef>
#include <cstdint>
#include <vector>

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

// Q rounded to the grid: Q̃. Every ring is kept in the input's own vertex order (deconstruct()
// orients Q exactly: outers counterclockwise, holes clockwise), with repeated consecutive vertices
// removed, even a ring that collapsed to a segment or a point. Then each ring of Q̃ is a
// straight-line homotopy of its ring of Q moving no point by more than kInputRounding, which is
// what H(Q, Q̃) <= 3/4 and the winding-number arguments rest on (README.md, "Input rounding").
struct GridInput {
  IRings rings;                        // Q̃, polygon by polygon (outer ring, then its holes)
  std::vector<std::size_t> first_ring; // index of each polygon's outer ring, then rings.size()

  // The rings of the polygons all of whose rounded rings keep three vertices and the orientation
  // of their ring in Q (outer counterclockwise, holes clockwise, nonzero area): a region A with
  // A ⊆ offset(Q, 3/4) (whole polygons are left out, never a hole alone), the one the level-set
  // walk of the YES certificate may use. `left_out` receives the other polygons' indices.
  [[nodiscard]] IRings solid_rings(std::vector<std::size_t>& left_out) const;

  // Whether some ring is thinner than the rounding can represent faithfully: its rounded area is
  // at most what moving its boundary by 2 kInputRounding sweeps (|2·area| <= 3·perimeter). Such a
  // ring has no grid point deep inside, and chords of its offsets pass within a unit of its far
  // side: the fast engine may stay UNDECIDED where exact arithmetic decides. (Completeness
  // only: no certificate depends on this test.)
  [[nodiscard]] bool has_thin_ring() const;
};

class GridFrame {
 public:
  // Chooses the scale for q and the parameters; throws InvalidInput when the coordinate
  // extent is more than 2^24 times delta (the grid would need more than 2^30 units).
  GridFrame(const PolygonSet& q, const DeconstructParams& params);

  // Length in grid units (rounded to double: relative error 2^-53).
  [[nodiscard]] double units(const Rational& length) const;
  // Length in grid units as doubles that enclose the exact value (CGAL::to_interval).
  [[nodiscard]] Bounds bounds(const Rational& length) const;

  // q (oriented: outers counterclockwise, holes clockwise) rounded to the grid, every ring kept.
  [[nodiscard]] GridInput round(const PolygonSet& q) const;
  [[nodiscard]] IPt round(const ExactPoint& p) const;

  // Exact rational polygon set of integer rings given as outers with their holes.
  [[nodiscard]] ExactPoint exact(IPt p) const;

  [[nodiscard]] int scale_exponent() const { return k_; }

 private:
  int k_ = 0;
  mpz_class tx_, ty_;
};

} // namespace penshape::fast
