#pragma once
// A polygonal region held as an exact CGAL polygon set (Epeck), behind a CGAL-free interface
// so that only exact_region.cpp pays CGAL's compile cost. Internal to core.
#include <cstddef>
#include <memory>

#include "penshape/core/base.hpp"
#include "penshape/core/polygon_set.hpp"

namespace penshape::detail {

class ExactRegion {
 public:
  ExactRegion();
  ~ExactRegion();
  ExactRegion(ExactRegion&&) noexcept;
  ExactRegion& operator=(ExactRegion&&) noexcept;
  ExactRegion(const ExactRegion&) = delete;
  ExactRegion& operator=(const ExactRegion&) = delete;

  // Precondition: a valid region (validate_region) with outer rings counterclockwise and holes
  // clockwise (normalize_orientation).
  static ExactRegion from(const PolygonSet& set);
  [[nodiscard]] PolygonSet to_polygon_set() const;

  [[nodiscard]] bool empty() const;
  [[nodiscard]] std::size_t vertex_count() const;

  // X ⊕ K for a convex counterclockwise ring K (a disk approximation). One Minkowski sum per
  // polygon with holes (reduced convolution), then one batched union.
  [[nodiscard]] ExactRegion minkowski_sum(const Ring& convex, const CancelHook& cancel) const;
  // (X^C ⊕ K)^C, computed inside a box around X wider than K so the box's border never
  // reaches X; one batched union of the sums and a single difference.
  [[nodiscard]] ExactRegion inset(const Ring& convex, const CancelHook& cancel) const;
  // other ⊆ *this, exactly.
  [[nodiscard]] bool contains(const ExactRegion& other) const;
  // X \ other, exactly (the closure of the difference).
  [[nodiscard]] ExactRegion minus(const ExactRegion& other) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace penshape::detail
