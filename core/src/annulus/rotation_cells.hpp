#pragma once
// Cells of (tx, ty, theta) for the branch-and-bound searches of rotation.hpp (method 3): the
// translation is that of the points rotated by -theta about their centroid (RotatedFrame).
#include <utility>

#include "prepared_annulus.hpp"
#include "rotation_internal.hpp"

namespace penshape::annulus::detail {

struct CellBox {
  double tx, ty, hx, hy; // translation centre and half-sizes
  double lo, hi;         // angle range
};

// How far a cell moves point i (template frame) from its position at the cell's sample angle and
// centre: translation half-diagonal + rho_i * angle reach (chord <= arc), rounded up.
struct CellReach {
  RotatedFrame::Angle angle;
  double translation;
  double reach;
};
CellReach cell_reach(const CellBox& cell);

// Template-frame position of point q at the cell's sample angle and centre.
inline PointD cell_position(const RotatedFrame& frame, const CellReach& r, const CellBox& cell,
                            PointD q) {
  const PointD c = frame.centre();
  const double dx = q.x - c.x;
  const double dy = q.y - c.y;
  return {c.x + r.angle.c * dx + r.angle.s * dy - cell.tx,
          c.y - r.angle.s * dx + r.angle.c * dy - cell.ty};
}

// Every translation that puts some point into the annulus with bounding box `box` (padded).
CellBox translation_domain(const RotatedFrame& frame, const Box& box, double pad, double lo,
                           double hi);

// Below both resolutions the cell is not split.
bool at_resolution(const CellBox& cell, double angle_resolution, double min_half);

// Halves the dimension that moves the points most (rho: largest distance to the centroid).
std::pair<CellBox, CellBox> split_cell(const CellBox& cell, double rho, double angle_resolution,
                                       double min_half);

} // namespace penshape::annulus::detail
