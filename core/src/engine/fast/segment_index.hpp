#pragma once
// The fast engine's index over the edges of integer rings: the one segment grid
// (geometry/segment_grid.hpp) with each edge's ring and position, plus exact winding numbers by
// horizontal slabs in the grid's rows (only edges spanning the query's row are scanned).
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/segment_grid.hpp"
#include "int_geometry.hpp"

namespace penshape::fast {

struct Segment {
  IPt a;
  IPt b;
  std::uint32_t ring = 0;      // index of the ring in rings()
  std::uint32_t ring_size = 0; // its vertex count
  std::uint32_t pos = 0;       // edge index inside the ring (from vertex pos to pos + 1)
  [[nodiscard]] DPt da() const { return to_d(a); }
  [[nodiscard]] DPt db() const { return to_d(b); }
};

using SegmentGrid = detail::SegmentGrid<Segment>;

class SegmentIndex {
 public:
  // cell: preferred bucket size in grid units (enlarged so the grid stays small).
  SegmentIndex(const IRings& rings, double cell);

  [[nodiscard]] const SegmentGrid& grid() const { return grid_; }
  [[nodiscard]] const std::vector<Segment>& segments() const { return grid_.segments(); }
  [[nodiscard]] const IRings& rings() const { return rings_; }

  // The grid's box queries (segment_grid.hpp): f(index) once for every segment whose bounding
  // box meets the box (may over-report); find_near stops as soon as f returns true.
  template <class F>
  void for_each_near(double min_x, double min_y, double max_x, double max_y, F&& f) const {
    grid_.for_each_near(min_x, min_y, max_x, max_y, std::forward<F>(f));
  }
  template <class F>
  bool find_near(double min_x, double min_y, double max_x, double max_y, F&& f) const {
    return grid_.find_near(min_x, min_y, max_x, max_y, std::forward<F>(f));
  }

  // Exact winding number of p (nonzero = inside). Unspecified for p on an edge.
  [[nodiscard]] int winding(IPt p) const;
  // The same, ignoring the edges of one ring (p may lie on that ring).
  [[nodiscard]] int winding_excluding(IPt p, std::uint32_t ring) const;

  // Distance from p to the nearest edge, or `cutoff` if no edge is closer than cutoff.
  [[nodiscard]] double distance(DPt p, double cutoff) const { return grid_.distance(p, cutoff); }

 private:
  IRings rings_;
  SegmentGrid grid_;
  std::vector<std::uint32_t> row_start_, row_items_; // edges spanning each grid row's y-range
};

} // namespace penshape::fast
