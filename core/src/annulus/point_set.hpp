#pragma once
// Point-set helpers shared by the sweeps: duplicates merged with weights, the points on the
// convex hull boundary (exact orientation), and a bucket grid (Section 3.2).
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "penshape/core/polygon_set.hpp"

namespace penshape::annulus::detail {

struct WeightedPoints {
  std::vector<PointD> points;      // distinct
  std::vector<std::size_t> weight; // how many input points coincide with each
};

WeightedPoints merge_duplicates(const std::vector<PointD>& points);

// on_hull[i]: point i lies on the boundary of the convex hull (vertices and edge points). Exact.
std::vector<bool> hull_boundary(const std::vector<PointD>& points);

// Buckets of size cell_w x cell_h; neighbours() lists the points of the 3x3 block around a point.
class BucketGrid {
 public:
  BucketGrid(const std::vector<PointD>& points, double cell_w, double cell_h);
  void neighbours(std::size_t i, std::vector<std::size_t>& out) const;

 private:
  [[nodiscard]] std::int64_t key(std::int64_t cx, std::int64_t cy) const;
  double x0_, y0_, w_, h_;
  std::vector<std::int64_t> cx_, cy_;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

} // namespace penshape::annulus::detail
