#include "point_set.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/exact_predicates.hpp"

namespace penshape::annulus::detail {

using ::penshape::detail::orientation; // the kernel's exact predicate

WeightedPoints merge_duplicates(const std::vector<PointD>& points) {
  std::vector<PointD> sorted = points;
  std::sort(sorted.begin(), sorted.end(),
            [](PointD a, PointD b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  WeightedPoints out;
  for (const PointD& q : sorted) {
    if (!out.points.empty() && out.points.back() == q) {
      ++out.weight.back();
    } else {
      out.points.push_back(q);
      out.weight.push_back(1);
    }
  }
  return out;
}

std::vector<bool> hull_boundary(const std::vector<PointD>& points) {
  // Points are distinct and sorted lexicographically (merge_duplicates). Monotone chain that keeps
  // collinear boundary points (pops only on strict right turns).
  const std::size_t n = points.size();
  std::vector<bool> on(n, false);
  if (n <= 3) {
    on.assign(n, true);
    return on;
  }
  std::vector<std::size_t> idx(n);
  for (std::size_t i = 0; i < n; ++i) idx[i] = i;
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    return points[a].x < points[b].x || (points[a].x == points[b].x && points[a].y < points[b].y);
  });
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::size_t> chain;
    for (std::size_t t = 0; t < n; ++t) {
      const std::size_t i = pass == 0 ? idx[t] : idx[n - 1 - t];
      while (chain.size() >= 2 &&
             orientation(points[chain[chain.size() - 2]], points[chain.back()], points[i]) < 0) {
        chain.pop_back();
      }
      chain.push_back(i);
    }
    for (std::size_t i : chain) on[i] = true;
  }
  return on;
}

BucketGrid::BucketGrid(const std::vector<PointD>& points, double cell_w, double cell_h)
    : x0_(0), y0_(0), w_(cell_w), h_(cell_h) {
  if (!points.empty()) {
    x0_ = points[0].x;
    y0_ = points[0].y;
    for (const PointD& q : points) {
      x0_ = std::min(x0_, q.x);
      y0_ = std::min(y0_, q.y);
    }
  }
  // Degenerate cells would overflow the keys: fall back to one bucket per 2^20 cells at most.
  double span_x = 0.0;
  double span_y = 0.0;
  for (const PointD& q : points) {
    span_x = std::max(span_x, q.x - x0_);
    span_y = std::max(span_y, q.y - y0_);
  }
  w_ = std::max(w_, span_x / 1048576.0);
  h_ = std::max(h_, span_y / 1048576.0);
  if (!(w_ > 0.0)) w_ = 1.0;
  if (!(h_ > 0.0)) h_ = 1.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    cx_.push_back(static_cast<std::int64_t>(std::floor((points[i].x - x0_) / w_)));
    cy_.push_back(static_cast<std::int64_t>(std::floor((points[i].y - y0_) / h_)));
    cells_[key(cx_.back(), cy_.back())].push_back(i);
  }
}

std::int64_t BucketGrid::key(std::int64_t cx, std::int64_t cy) const {
  return (cx + 2) * 4194304 + (cy + 2);
}

void BucketGrid::neighbours(std::size_t i, std::vector<std::size_t>& out) const {
  out.clear();
  for (std::int64_t dx = -1; dx <= 1; ++dx) {
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      const auto it = cells_.find(key(cx_[i] + dx, cy_[i] + dy));
      if (it == cells_.end()) continue;
      for (std::size_t j : it->second) {
        if (j != i) out.push_back(j);
      }
    }
  }
}

} // namespace penshape::annulus::detail
