#pragma once
// A uniform bucket grid over the edges of integer rings: "which edges come near this box" and
// exact winding numbers by horizontal slabs (only edges spanning the query's row are scanned).
#include <cstddef>
#include <cstdint>
#include <vector>

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

class SegmentIndex {
 public:
  // cell: preferred bucket size in grid units (enlarged so the grid stays small).
  SegmentIndex(const IRings& rings, double cell);

  [[nodiscard]] const std::vector<Segment>& segments() const { return segments_; }
  [[nodiscard]] const IRings& rings() const { return rings_; }

  // Calls f(index) once for every segment whose bounding box meets the box (may over-report).
  template <class F>
  void for_each_near(double min_x, double min_y, double max_x, double max_y, F&& f) const {
    (void)find_near(min_x, min_y, max_x, max_y, [&f](std::size_t s) {
      f(s);
      return false;
    });
  }

  // Calls f(index) as for_each_near, stopping as soon as f returns true (returns whether it did).
  template <class F>
  bool find_near(double min_x, double min_y, double max_x, double max_y, F&& f) const {
    if (segments_.empty()) return false;
    const int x0 = clamp_col(min_x), x1 = clamp_col(max_x);
    const int y0 = clamp_row(min_y), y1 = clamp_row(max_y);
    ++stamp_;
    for (int gy = y0; gy <= y1; ++gy) {
      for (int gx = x0; gx <= x1; ++gx) {
        const std::size_t c = static_cast<std::size_t>(gy) * static_cast<std::size_t>(nx_) +
                              static_cast<std::size_t>(gx);
        for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
          const std::uint32_t s = cell_items_[k];
          if (seen_[s] == stamp_) continue;
          seen_[s] = stamp_;
          if (f(static_cast<std::size_t>(s))) return true;
        }
      }
    }
    return false;
  }

  // Exact winding number of p (nonzero = inside). Unspecified for p on an edge.
  [[nodiscard]] int winding(IPt p) const;
  // The same, ignoring the edges of one ring (p may lie on that ring).
  [[nodiscard]] int winding_excluding(IPt p, std::uint32_t ring) const;

  // Distance from p to the nearest edge, or `cutoff` if no edge is closer than cutoff.
  [[nodiscard]] double distance(DPt p, double cutoff) const;

 private:
  [[nodiscard]] int clamp_col(double x) const;
  [[nodiscard]] int clamp_row(double y) const;

  IRings rings_;
  std::vector<Segment> segments_;
  double origin_x_ = 0.0, origin_y_ = 0.0, cell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> cell_start_, cell_items_; // CSR bucket lists
  std::vector<std::uint32_t> row_start_, row_items_;   // edges spanning each row's y-range
  mutable std::vector<std::uint64_t> seen_;
  mutable std::uint64_t stamp_ = 0;
};

} // namespace penshape::fast
