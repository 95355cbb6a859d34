#pragma once
// A uniform grid of line segments for distance queries near a point (the ink certificate's
// spatial index over the ink polygon's edges and over a sampled ellipse).
#include <cstdint>
#include <vector>

#include "geometry.hpp"

namespace penshape::recognize_detail {

struct Segment {
  PointD a;
  PointD b;
};

class SegmentIndex {
 public:
  // Cells of side `cell` (> 0) over the segments' bounding box; at most max_cells cells (the side
  // grows when needed). Every segment is listed in every cell its bounding band crosses, padded
  // by one cell so that rounding cannot leave it out of a cell it touches.
  SegmentIndex(std::vector<Segment> segments, double cell, std::size_t max_cells = 1 << 20);

  // True when some segment is at distance <= radius from p (exact up to rounding).
  [[nodiscard]] bool any_within(PointD p, double radius) const;
  // False only when every segment is certainly farther than radius from p (interval arithmetic
  // with directed rounding through geometry/distance_kernel.hpp): a selection that never misses.
  [[nodiscard]] bool maybe_within(PointD p, double radius) const;

  // The distance from p to the nearest segment when it exceeds `floor`; otherwise some value
  // <= floor (the search stops at the first segment within floor). +inf without segments.
  [[nodiscard]] double nearest_above(PointD p, double floor) const;
  // The same, and in `id` the segment that gave it (a proposal for a certified evaluation).
  [[nodiscard]] double nearest_above(PointD p, double floor, std::uint32_t& id) const;

  [[nodiscard]] const Segment& segment(std::uint32_t id) const { return segments_[id]; }

  [[nodiscard]] bool empty() const { return segments_.empty(); }

 private:
  [[nodiscard]] std::int64_t column(double x) const;
  [[nodiscard]] std::int64_t row(double y) const;

  std::vector<Segment> segments_;
  PointD origin_;
  double cell_ = 1.0;
  std::int64_t nx_ = 0;
  std::int64_t ny_ = 0;
  std::vector<std::uint32_t> start_; // CSR: segments of cell c are ids_[start_[c]..start_[c+1])
  std::vector<std::uint32_t> ids_;
};

} // namespace penshape::recognize_detail
