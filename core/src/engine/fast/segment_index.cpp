#include "segment_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace penshape::fast {
namespace {

constexpr int kMaxCellsPerAxis = 1024;

} // namespace

SegmentIndex::SegmentIndex(const IRings& rings, double cell) : rings_(rings) {
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  for (std::size_t r = 0; r < rings_.size(); ++r) {
    const IRing& ring = rings_[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      segments_.push_back({ring[i], ring[(i + 1) % ring.size()], static_cast<std::uint32_t>(r),
                           static_cast<std::uint32_t>(ring.size()), static_cast<std::uint32_t>(i)});
      min_x = std::min(min_x, static_cast<double>(ring[i].x));
      min_y = std::min(min_y, static_cast<double>(ring[i].y));
      max_x = std::max(max_x, static_cast<double>(ring[i].x));
      max_y = std::max(max_y, static_cast<double>(ring[i].y));
    }
  }
  seen_.assign(segments_.size(), 0);
  if (segments_.empty()) return;
  const double extent = std::max(max_x - min_x, max_y - min_y) + 1.0;
  cell_ = std::max({cell, extent / kMaxCellsPerAxis, 1.0});
  origin_x_ = min_x;
  origin_y_ = min_y;
  nx_ = static_cast<int>((max_x - min_x) / cell_) + 1;
  ny_ = static_cast<int>((max_y - min_y) / cell_) + 1;

  // Two passes (count, fill) for compact bucket lists.
  const std::size_t ncells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  cell_start_.assign(ncells + 1, 0);
  row_start_.assign(static_cast<std::size_t>(ny_) + 1, 0);
  auto visit = [&](auto&& on_cell, auto&& on_row) {
    for (std::size_t s = 0; s < segments_.size(); ++s) {
      const Segment& g = segments_[s];
      const int x0 = clamp_col(static_cast<double>(std::min(g.a.x, g.b.x)));
      const int x1 = clamp_col(static_cast<double>(std::max(g.a.x, g.b.x)));
      const int y0 = clamp_row(static_cast<double>(std::min(g.a.y, g.b.y)));
      const int y1 = clamp_row(static_cast<double>(std::max(g.a.y, g.b.y)));
      for (int gy = y0; gy <= y1; ++gy) {
        on_row(static_cast<std::size_t>(gy), s);
        for (int gx = x0; gx <= x1; ++gx) {
          on_cell(static_cast<std::size_t>(gy) * static_cast<std::size_t>(nx_) +
                      static_cast<std::size_t>(gx),
                  s);
        }
      }
    }
  };
  visit([&](std::size_t c, std::size_t) { ++cell_start_[c + 1]; },
        [&](std::size_t r, std::size_t) { ++row_start_[r + 1]; });
  for (std::size_t c = 0; c < ncells; ++c) cell_start_[c + 1] += cell_start_[c];
  for (std::size_t r = 0; r + 1 < row_start_.size(); ++r) row_start_[r + 1] += row_start_[r];
  cell_items_.resize(cell_start_.back());
  row_items_.resize(row_start_.back());
  std::vector<std::uint32_t> cell_fill(cell_start_.begin(), cell_start_.end() - 1);
  std::vector<std::uint32_t> row_fill(row_start_.begin(), row_start_.end() - 1);
  visit([&](std::size_t c,
            std::size_t s) { cell_items_[cell_fill[c]++] = static_cast<std::uint32_t>(s); },
        [&](std::size_t r, std::size_t s) {
          row_items_[row_fill[r]++] = static_cast<std::uint32_t>(s);
        });
}

int SegmentIndex::clamp_col(double x) const {
  const double c = std::floor((x - origin_x_) / cell_);
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(nx_ - 1)));
}

int SegmentIndex::clamp_row(double y) const {
  const double c = std::floor((y - origin_y_) / cell_);
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(ny_ - 1)));
}

int SegmentIndex::winding(IPt p) const {
  return winding_excluding(p, static_cast<std::uint32_t>(-1));
}

int SegmentIndex::winding_excluding(IPt p, std::uint32_t ring) const {
  if (segments_.empty()) return 0;
  // Every edge crossing the horizontal line through p spans p.y, so it is listed in p's row
  // (rows are clamped, and an edge's rows cover its whole y-range).
  const std::size_t row = static_cast<std::size_t>(clamp_row(static_cast<double>(p.y)));
  int w = 0;
  for (std::uint32_t k = row_start_[row]; k < row_start_[row + 1]; ++k) {
    const Segment& g = segments_[row_items_[k]];
    if (g.ring == ring) continue;
    if (g.a.y <= p.y) {
      if (g.b.y > p.y && orientation(g.a, g.b, p) > 0) ++w;
    } else if (g.b.y <= p.y && orientation(g.a, g.b, p) < 0) {
      --w;
    }
  }
  return w;
}

double SegmentIndex::distance(DPt p, double cutoff) const {
  double best = cutoff;
  for_each_near(p.x - cutoff, p.y - cutoff, p.x + cutoff, p.y + cutoff, [&](std::size_t s) {
    best = std::min(best, point_segment_distance(p, segments_[s].da(), segments_[s].db()));
  });
  return best;
}

} // namespace penshape::fast
