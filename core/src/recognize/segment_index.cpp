// Uniform segment grid (see segment_index.hpp).
#include "segment_index.hpp"

#include <cmath>
#include <limits>

namespace penshape::recognize_detail {

SegmentIndex::SegmentIndex(std::vector<Segment> segments, double cell, std::size_t max_cells)
    : segments_(std::move(segments)) {
  if (segments_.empty()) return;
  double xlo = INFINITY, ylo = INFINITY, xhi = -INFINITY, yhi = -INFINITY;
  for (const Segment& s : segments_) {
    xlo = std::min({xlo, s.a.x, s.b.x});
    xhi = std::max({xhi, s.a.x, s.b.x});
    ylo = std::min({ylo, s.a.y, s.b.y});
    yhi = std::max({yhi, s.a.y, s.b.y});
  }
  const double w = xhi - xlo, h = yhi - ylo;
  cell_ = std::max(
      {cell, std::sqrt(w * h / static_cast<double>(max_cells)), 1e-9 * std::max({w, h, 1.0})});
  origin_ = {xlo, ylo};
  nx_ = static_cast<std::int64_t>(std::floor(w / cell_)) + 1;
  ny_ = static_cast<std::int64_t>(std::floor(h / cell_)) + 1;
  // Cells crossed by each segment: per row of cells, the x-range of the segment inside the row's
  // band, one cell of padding each side (two passes: count, then fill).
  std::vector<std::uint32_t> count(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
  auto for_cells = [&](const Segment& s, auto&& visit) {
    const std::int64_t r0 = std::max<std::int64_t>(0, row(std::min(s.a.y, s.b.y)) - 1);
    const std::int64_t r1 = std::min(ny_ - 1, row(std::max(s.a.y, s.b.y)) + 1);
    for (std::int64_t r = r0; r <= r1; ++r) {
      const double band_lo = origin_.y + static_cast<double>(r) * cell_;
      const double band_hi = band_lo + cell_;
      double x0 = std::min(s.a.x, s.b.x), x1 = std::max(s.a.x, s.b.x);
      const double dy = s.b.y - s.a.y;
      if (dy != 0.0) {
        const double t0 = std::clamp((band_lo - s.a.y) / dy, 0.0, 1.0);
        const double t1 = std::clamp((band_hi - s.a.y) / dy, 0.0, 1.0);
        const double xa = s.a.x + t0 * (s.b.x - s.a.x), xb = s.a.x + t1 * (s.b.x - s.a.x);
        x0 = std::min(xa, xb);
        x1 = std::max(xa, xb);
      }
      const std::int64_t c0 = std::max<std::int64_t>(0, column(x0) - 1);
      const std::int64_t c1 = std::min(nx_ - 1, column(x1) + 1);
      for (std::int64_t c = c0; c <= c1; ++c) visit(static_cast<std::size_t>(r * nx_ + c));
    }
  };
  for (const Segment& s : segments_) for_cells(s, [&](std::size_t c) { ++count[c + 1]; });
  for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  start_ = count;
  ids_.resize(count.back());
  for (std::uint32_t i = 0; i < segments_.size(); ++i) {
    for_cells(segments_[i], [&](std::size_t c) { ids_[count[c]++] = i; });
  }
}

std::int64_t SegmentIndex::column(double x) const {
  const double c = std::floor((x - origin_.x) / cell_);
  return static_cast<std::int64_t>(std::clamp(c, -1e15, 1e15));
}

std::int64_t SegmentIndex::row(double y) const {
  const double r = std::floor((y - origin_.y) / cell_);
  return static_cast<std::int64_t>(std::clamp(r, -1e15, 1e15));
}

bool SegmentIndex::any_within(PointD p, double radius) const {
  if (segments_.empty()) return false;
  const std::int64_t c0 = std::max<std::int64_t>(0, column(p.x - radius));
  const std::int64_t c1 = std::min(nx_ - 1, column(p.x + radius));
  const std::int64_t r0 = std::max<std::int64_t>(0, row(p.y - radius));
  const std::int64_t r1 = std::min(ny_ - 1, row(p.y + radius));
  const double r2 = radius * radius;
  for (std::int64_t r = r0; r <= r1; ++r) {
    for (std::int64_t c = c0; c <= c1; ++c) {
      const auto cell = static_cast<std::size_t>(r * nx_ + c);
      for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
        const Segment& s = segments_[ids_[k]];
        if (segment_distance2(p, s.a, s.b) <= r2) return true;
      }
    }
  }
  return false;
}

bool SegmentIndex::maybe_within(PointD p, double radius) const {
  if (segments_.empty()) return false;
  // The cells as any_within finds them: each segment is listed one cell beyond the cells it
  // crosses, so rounding in the cell arithmetic cannot hide it.
  const std::int64_t c0 = std::max<std::int64_t>(0, column(p.x - radius));
  const std::int64_t c1 = std::min(nx_ - 1, column(p.x + radius));
  const std::int64_t r0 = std::max<std::int64_t>(0, row(p.y - radius));
  const std::int64_t r1 = std::min(ny_ - 1, row(p.y + radius));
  const CGAL::Protect_FPU_rounding<true> rounding;
  const double r2 = CGAL::square(detail::IntervalNT(radius)).sup();
  const detail::IPoint ip = detail::enclose(p);
  for (std::int64_t r = r0; r <= r1; ++r) {
    for (std::int64_t c = c0; c <= c1; ++c) {
      const auto cell = static_cast<std::size_t>(r * nx_ + c);
      for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
        const Segment& s = segments_[ids_[k]];
        const detail::IntervalNT d2 =
            detail::squared_distance_enclosure(ip, detail::enclose(s.a), detail::enclose(s.b));
        if (d2.inf() <= r2) return true;
      }
    }
  }
  return false;
}

double SegmentIndex::nearest_above(PointD p, double floor) const {
  std::uint32_t id = 0;
  return nearest_above(p, floor, id);
}

double SegmentIndex::nearest_above(PointD p, double floor, std::uint32_t& id) const {
  if (segments_.empty()) return INFINITY;
  const std::int64_t pc = column(p.x), pr = row(p.y);
  // Rings of cells around p's cell: after ring k every unvisited cell is at least k cells
  // (k * cell) away from p, so the search ends once the best distance is within that.
  const std::int64_t last_ring = std::max({std::int64_t{0}, pc, nx_ - 1 - pc, pr, ny_ - 1 - pr});
  double best2 = INFINITY;
  const double floor2 = floor > 0 ? floor * floor : 0.0;
  auto visit = [&](std::int64_t r, std::int64_t c) {
    const auto cell = static_cast<std::size_t>(r * nx_ + c);
    for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
      const Segment& s = segments_[ids_[k]];
      const double d2 = segment_distance2(p, s.a, s.b);
      if (d2 < best2) {
        best2 = d2;
        id = ids_[k];
      }
      if (best2 <= floor2) return true;
    }
    return false;
  };
  // Rings that lie wholly outside the grid hold nothing: start at the first that meets it.
  const std::int64_t first_ring =
      std::max({std::int64_t{0}, -pc, pc - (nx_ - 1), -pr, pr - (ny_ - 1)});
  for (std::int64_t k = first_ring; k <= last_ring; ++k) {
    const std::int64_t c_lo = std::max<std::int64_t>(0, pc - k);
    const std::int64_t c_hi = std::min(nx_ - 1, pc + k);
    const std::int64_t r_lo = std::max<std::int64_t>(0, pr - k + 1);
    const std::int64_t r_hi = std::min(ny_ - 1, pr + k - 1);
    for (const std::int64_t r : {pr - k, pr + k}) {
      if (r < 0 || r >= ny_) continue;
      for (std::int64_t c = c_lo; c <= c_hi; ++c) {
        if (visit(r, c)) return std::sqrt(best2);
      }
      if (k == 0) break; // ring 0 is one cell
    }
    for (const std::int64_t c : {pc - k, pc + k}) {
      if (k == 0 || c < 0 || c >= nx_) continue;
      for (std::int64_t r = r_lo; r <= r_hi; ++r) {
        if (visit(r, c)) return std::sqrt(best2);
      }
    }
    const double reach = static_cast<double>(k) * cell_;
    if (best2 <= reach * reach) break;
  }
  return std::sqrt(best2);
}

} // namespace penshape::recognize_detail
