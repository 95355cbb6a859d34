// The fast engine's ring-edge index: the shared segment grid plus winding slabs (see
// segment_index.hpp).
#include "segment_index.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace penshape::fast {
namespace {

constexpr int kMaxCellsPerAxis = 1024;

std::vector<Segment> ring_edges(const IRings& rings) {
  std::vector<Segment> out;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const IRing& ring = rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      out.push_back({ring[i], ring[(i + 1) % ring.size()], static_cast<std::uint32_t>(r),
                     static_cast<std::uint32_t>(ring.size()), static_cast<std::uint32_t>(i)});
    }
  }
  return out;
}

// The bucket side: the preferred cell, at least one grid unit, and at most kMaxCellsPerAxis
// cells along the longer axis.
double cell_size(const IRings& rings, double cell) {
  std::int64_t min_x = std::numeric_limits<std::int64_t>::max(), min_y = min_x;
  std::int64_t max_x = std::numeric_limits<std::int64_t>::min(), max_y = max_x;
  for (const IRing& ring : rings) {
    for (const IPt& p : ring) {
      min_x = std::min(min_x, p.x);
      max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y);
      max_y = std::max(max_y, p.y);
    }
  }
  if (min_x > max_x) return std::max(cell, 1.0);
  const double extent = static_cast<double>(std::max(max_x - min_x, max_y - min_y)) + 1.0;
  return std::max({cell, extent / kMaxCellsPerAxis, 1.0});
}

} // namespace

SegmentIndex::SegmentIndex(const IRings& rings, double cell)
    : rings_(rings), grid_(ring_edges(rings), cell_size(rings, cell)) {
  // Each edge in every row its y-range meets (two passes: count, fill), rows as the grid's;
  // each edge's rows are computed once, in the first pass.
  const std::vector<Segment>& segs = grid_.segments();
  if (segs.empty()) return;
  const auto rows = static_cast<std::size_t>(grid_.row_count());
  row_start_.assign(rows + 1, 0);
  std::vector<std::pair<int, int>> spans(segs.size());
  for (std::size_t s = 0; s < segs.size(); ++s) {
    const Segment& g = segs[s];
    spans[s] = {grid_.clamped_row(static_cast<double>(std::min(g.a.y, g.b.y))),
                grid_.clamped_row(static_cast<double>(std::max(g.a.y, g.b.y)))};
  }
  auto visit = [&](auto&& on_row) {
    for (std::size_t s = 0; s < segs.size(); ++s) {
      for (int gy = spans[s].first; gy <= spans[s].second; ++gy) {
        on_row(static_cast<std::size_t>(gy), s);
      }
    }
  };
  visit([&](std::size_t r, std::size_t) { ++row_start_[r + 1]; });
  for (std::size_t r = 0; r < rows; ++r) row_start_[r + 1] += row_start_[r];
  row_items_.resize(row_start_.back());
  std::vector<std::uint32_t> fill(row_start_.begin(), row_start_.end() - 1);
  visit(
      [&](std::size_t r, std::size_t s) { row_items_[fill[r]++] = static_cast<std::uint32_t>(s); });
}

int SegmentIndex::winding(IPt p) const {
  return winding_excluding(p, static_cast<std::uint32_t>(-1));
}

int SegmentIndex::winding_excluding(IPt p, std::uint32_t ring) const {
  const std::vector<Segment>& segs = grid_.segments();
  if (segs.empty()) return 0;
  // Every edge crossing the horizontal line through p spans p.y, so it is listed in p's row
  // (rows are clamped, and an edge's rows cover its whole y-range).
  const auto row = static_cast<std::size_t>(grid_.clamped_row(static_cast<double>(p.y)));
  int w = 0;
  for (std::uint32_t k = row_start_[row]; k < row_start_[row + 1]; ++k) {
    const Segment& g = segs[row_items_[k]];
    if (g.ring == ring) continue;
    if (g.a.y <= p.y) {
      if (g.b.y > p.y && orientation(g.a, g.b, p) > 0) ++w;
    } else if (g.b.y <= p.y && orientation(g.a, g.b, p) < 0) {
      --w;
    }
  }
  return w;
}

} // namespace penshape::fast
