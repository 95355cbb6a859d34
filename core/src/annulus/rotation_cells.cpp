// Cell geometry shared by the (tx, ty, theta) branch-and-bound searches.
#include "rotation_cells.hpp"

#include <algorithm>
#include <cmath>

namespace penshape::annulus::detail {

CellReach cell_reach(const CellBox& cell) {
  CellReach r{};
  r.angle = RotatedFrame::angle(0.5 * (cell.lo + cell.hi));
  r.reach = angle_reach(r.angle, cell.lo, cell.hi);
  r.translation = std::hypot(cell.hx, cell.hy) * (1.0 + 1e-12);
  return r;
}

CellBox translation_domain(const RotatedFrame& frame, const Box& box, double pad, double lo,
                           double hi) {
  // Rotated points stay within rho of the centroid; a covered point lies in t + box.
  const PointD c = frame.centre();
  const double rho = frame.rho();
  const double x0 = c.x - rho - box.x1 - pad;
  const double x1 = c.x + rho - box.x0 + pad;
  const double y0 = c.y - rho - box.y1 - pad;
  const double y1 = c.y + rho - box.y0 + pad;
  return {0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (x1 - x0), 0.5 * (y1 - y0), lo, hi};
}

bool at_resolution(const CellBox& cell, double angle_resolution, double min_half) {
  return 0.5 * (cell.hi - cell.lo) < angle_resolution && std::max(cell.hx, cell.hy) < min_half;
}

std::pair<CellBox, CellBox> split_cell(const CellBox& cell, double rho, double angle_resolution,
                                       double min_half) {
  CellBox a = cell;
  CellBox b = cell;
  const double angle_half = 0.5 * (cell.hi - cell.lo);
  const double shift = std::max(cell.hx, cell.hy);
  if ((rho * angle_half >= shift || shift < min_half) && angle_half >= angle_resolution) {
    a.hi = b.lo = 0.5 * (cell.lo + cell.hi);
  } else if (cell.hx >= cell.hy) {
    a.hx = b.hx = 0.5 * cell.hx;
    a.tx = cell.tx - a.hx;
    b.tx = cell.tx + b.hx;
  } else {
    a.hy = b.hy = 0.5 * cell.hy;
    a.ty = cell.ty - a.hy;
    b.ty = cell.ty + b.hy;
  }
  return {a, b};
}

} // namespace penshape::annulus::detail
