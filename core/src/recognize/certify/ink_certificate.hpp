#pragma once
// The ink-level certificate (argument in penshape/core/ink_certificate.hpp): the stroke's ink
// polygon prepared once per stroke for grid sampling, and the bound for one clean shape.
#include <cstdint>
#include <vector>

#include "penshape/core/ink.hpp"
#include "penshape/core/recognize.hpp"
#include "recognize/fitting/clean_shape.hpp"
#include "recognize/fitting/geometry.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {

// Where an edge of Q crosses a grid row: an interval holding the exact x (directed rounding).
struct RowCrossing {
  double lo;
  double hi;
};

// Q' (Q's vertices rounded to doubles) : its edges in a segment grid and, per grid row, the
// crossings sorted by lo (inside/outside along the row by parity, certain when no crossing's
// interval holds the grid point).
struct InkRegion {
  double hausdorff_bound = 0.0; // InkPolygon::hausdorff_bound
  double rounding = 0.0;        // >= H(Q, Q'): the largest vertex rounding, rounded up
  double h = 0.0;               // grid spacing
  PointD origin;                // grid points are origin + (i h, j h), i and j integers
  PointD lo, hi;                // Q's bounding box
  double magnitude = 0.0;       // largest |coordinate| of Q
  double widest = 0.0;          // the widest crossing interval (for the parity's ambiguity)
  std::int64_t first_row = 0;   // rows[k] is grid row first_row + k
  std::vector<std::vector<RowCrossing>> rows;
  SegmentIndex edges{{}, 1.0};
};

// The sampling grid's lines over a box: the coordinates o + i h (i = first..last) as doubles,
// nondecreasing, and `reach`, rounded up, >= the distance from any point of the box they span to
// the nearest grid point (half the diagonal of the widest cell actually used).
struct GridLines {
  std::vector<double> x, y;
  std::int64_t first_i = 0, first_j = 0; // x[k] = o.x + (first_i + k) h, the same for y
  double reach = 0.0;
};
// The lines covering [lo, hi] (lo <= hi, finite) on the grid origin + (i h, j h).
GridLines grid_lines(PointD origin, double h, PointD lo, PointD hi);

// Throws InvalidInput when Q is empty or has non-finite coordinates.
InkRegion prepare_ink(const InkPolygon& ink, double epsilon);

// How the grid is visited: kPruned skips blocks of grid points proven not to change either
// maximum; kFlat visits every grid point (kept for the tests and the bench, which check that both
// give the same bound, bit for bit).
enum class InkScan { kPruned, kFlat };

// Upper bound on H(shape ⊕ D_r, true stroke ink) (Certificate::method "ink").
Certificate certify_ink(const InkRegion& q, const CleanShape& shape, double epsilon,
                        double pen_radius, InkScan how = InkScan::kPruned);

} // namespace penshape::recognize_detail
