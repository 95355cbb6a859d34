#pragma once
// The edges of a polygon set in a uniform grid, for the verifier's queries: is a point inside
// (even-odd), is some edge within a distance, are all edges beyond it. Exact answers (intervals
// with a rational fallback); the grid only narrows which edges are examined, with padded boxes
// so that no edge that could matter is skipped. Approximate distances (doubles) are offered for
// proposing points, never for deciding. Internal to core/src/verify.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "verify/verify_kernel.hpp"

namespace penshape::verify {

class EdgeSet {
 public:
  // `typical_query` is the usual query distance (sizes the grid).
  EdgeSet(const PolygonSet& set, double typical_query);

  [[nodiscard]] bool empty() const { return edges_.empty(); }
  // Inside the region by the even-odd rule; a point on an edge may go either way.
  [[nodiscard]] bool contains(const VPoint& c) const;
  // Some edge with d(c, edge) <= l.
  [[nodiscard]] bool any_within(const VPoint& c, const Threshold& l) const;
  // Every edge with d(c, edge) > l.
  [[nodiscard]] bool all_beyond(const VPoint& c, const Threshold& l) const;
  // min(cap, distance to the nearest edge), in doubles (proposals only).
  [[nodiscard]] double approx_distance(double x, double y, double cap) const;
  [[nodiscard]] bool approx_contains(double x, double y) const;
  using Segment = std::pair<const VPoint*, const VPoint*>;
  // Every edge that may come within `reach` of (x, y) (a superset: none that does is missed).
  [[nodiscard]] std::vector<Segment> edges_near(double x, double y, double reach) const;
  // The edge nearest to (x, y) within cap, by doubles (a proposal); nullopt when none.
  [[nodiscard]] std::optional<Segment> approx_nearest_edge(double x, double y, double cap) const;

  // Bounding box of the vertices, exactly.
  [[nodiscard]] const ExactPoint& low() const { return low_; }
  [[nodiscard]] const ExactPoint& high() const { return high_; }

 private:
  struct Edge {
    std::uint32_t a;
    std::uint32_t b;
  };
  template <typename F>
  bool for_edges_near(double x, double y, double reach, F&& f) const;
  [[nodiscard]] std::size_t col(double x) const;
  [[nodiscard]] std::size_t row(double y) const;

  std::vector<VPoint> points_;
  std::vector<double> px_, py_;
  std::vector<Edge> edges_;
  ExactPoint low_, high_;
  double x0_ = 0, y0_ = 0, cell_ = 1, pad_ = 0;
  std::size_t cols_ = 1, rows_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;  // edges near each cell
  std::vector<std::vector<std::uint32_t>> strips_; // edges whose y-range meets each row
  mutable std::vector<std::uint32_t> stamp_;
  mutable std::uint32_t epoch_ = 0;
};

} // namespace penshape::verify
