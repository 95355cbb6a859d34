#pragma once
// The one spatial index over line segments, for every point type (doubles for the recognizer,
// integer ring edges for the fast engine), in the style of CGAL's traits: a SegmentTraits
// specialisation says how to read a segment's ends as doubles. A uniform grid buckets each
// segment in every cell its bounding box meets; the box query (find_near) is the primitive and
// the nearest / within queries are built on it with geometry/distance_kernel.hpp, the certified
// ones (maybe_within, for_each_not_farther) with outward rounding and intervals. Header-only so
// that the engines' hot loops inline. Internal to core.
//
// Why no cell is ever missed: the exact cell of a coordinate, k(v) = floor((v - origin) / cell)
// in real arithmetic (clamped into the grid), is monotone in v. Doubles compute (v - origin) /
// cell with some rounding mode that the caller chose (the certified queries run under upward
// rounding, everything else to nearest), so they can land on either side of a cell line; instead
// of trusting one mode, every coordinate is given the span of cells [k_lo(v), k_hi(v)] that
// holds k(v) in every rounding mode (cell_span, the error bound derived there). A segment is
// filed in the spans of its box and a query scans the spans of its box. A segment whose box
// meets the query box has a coordinate v in both on each axis; k(v) lies between k(lo) and
// k(hi) for both boxes, hence in both spans: a segment is never missed, whatever the modes of
// filing and query.
//
// Threads: the queries built on visit_near (any_within, maybe_within, nearest_above) only read;
// those built on find_near (for_each_near, distance, nearest_closer_than, for_each_not_farther)
// mark segments already reported, so one grid serves one thread at a time for them.
#include <CGAL/FPU.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "geometry/distance_kernel.hpp"

namespace penshape::detail {

// How the grid reads a segment: its ends as doubles, exactly (double points trivially; the fast
// engine's integers are bounded by 2^31). The default reads members a and b with x and y.
template <class Segment>
struct SegmentTraits {
  static Point2<double> source(const Segment& s) {
    return {static_cast<double>(s.a.x), static_cast<double>(s.a.y)};
  }
  static Point2<double> target(const Segment& s) {
    return {static_cast<double>(s.b.x), static_cast<double>(s.b.y)};
  }
};

// A lower bound of max(a - b, 0) in the default rounding mode: a - b rounded to nearest, one ulp
// down when positive. The same value as max(std::nextafter(a - b, -inf), 0) without libm's call
// (4% of the fast engine's decision on KAZ): a positive double's predecessor is its bit pattern
// minus one (+inf's is the largest double, the smallest denormal's is 0).
inline double gap_below(double a, double b) {
  const double g = a - b;
  if (!(g > 0.0)) return 0.0;
  return std::bit_cast<double>(std::bit_cast<std::uint64_t>(g) - 1U);
}

// std::nextafter(x, +inf) and std::nextafter(x, -inf) without libm's call (the certified
// bounds take several per query: 2% of the fast engine's decision on KAZ). Finite nonzero x:
// the neighbour away from or towards zero is the bit pattern plus or minus one (the largest
// double's successor is +inf, -denorm_min's is -0); zeros step to the smallest denormal; +inf
// and NaN stay. next_down(x) = -next_up(-x) by symmetry.
inline double next_up(double x) {
  if (!(x < std::numeric_limits<double>::infinity())) return x;
  if (x == 0.0) return std::numeric_limits<double>::denorm_min();
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(x > 0.0 ? bits + 1U : bits - 1U);
}
inline double next_down(double x) { return -next_up(-x); }

// An axis-aligned box of doubles.
struct GridBox {
  double lo_x, lo_y, hi_x, hi_y;
};

template <class Segment, class Traits = SegmentTraits<Segment>>
class SegmentGrid {
 public:
  SegmentGrid() = default;
  // Cells of side `cell` (> 0) over the segments' bounding box, enlarged so that there are at
  // most about max_cells of them.
  SegmentGrid(std::vector<Segment> segments, double cell, std::size_t max_cells = 1 << 20)
      : segments_(std::move(segments)) {
    build(cell, max_cells);
  }

  [[nodiscard]] const std::vector<Segment>& segments() const { return segments_; }
  [[nodiscard]] const Segment& segment(std::size_t id) const { return segments_[id]; }
  [[nodiscard]] bool empty() const { return segments_.empty(); }
  [[nodiscard]] static Point2<double> source(const Segment& s) { return Traits::source(s); }
  [[nodiscard]] static Point2<double> target(const Segment& s) { return Traits::target(s); }

  // The grid's rows: a y value's row, clamped into the grid (layers such as the fast engine's
  // winding slabs share the grid's frame through these).
  [[nodiscard]] int row_count() const { return ny_; }
  [[nodiscard]] int clamped_row(double y) const { return clamp_cell(y, origin_y_, ny_); }

  // Calls f(id) for every cell listing of a segment whose bounding box may meet the box (a
  // segment may come more than once): for queries that stop at the first hit.
  template <class F>
  bool visit_near(const GridBox& box, F&& f) const {
    if (segments_.empty() || !(box.lo_x <= box.hi_x) || !(box.lo_y <= box.hi_y)) return false;
    const int x0 = cell_span(box.lo_x, origin_x_, nx_).lo;
    const int x1 = cell_span(box.hi_x, origin_x_, nx_).hi;
    const int y0 = cell_span(box.lo_y, origin_y_, ny_).lo;
    const int y1 = cell_span(box.hi_y, origin_y_, ny_).hi;
    for (int gy = y0; gy <= y1; ++gy) {
      const std::size_t base = static_cast<std::size_t>(gy) * static_cast<std::size_t>(nx_);
      for (int gx = x0; gx <= x1; ++gx) {
        const std::size_t c = base + static_cast<std::size_t>(gx);
        for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
          if (f(static_cast<std::size_t>(cell_items_[k]))) return true;
        }
      }
    }
    return false;
  }

  // Calls f(id) once for every segment whose bounding box meets the box (and perhaps a few
  // more), stopping as soon as f returns true (returns whether it did). Not reentrant: a grid
  // is queried by one thread at a time.
  template <class F>
  bool find_near(double min_x, double min_y, double max_x, double max_y, F&& f) const {
    if (seen_.size() != segments_.size()) seen_.assign(segments_.size(), 0);
    const std::uint64_t stamp = ++stamp_;
    return visit_near({min_x, min_y, max_x, max_y}, [&](std::size_t s) {
      if (seen_[s] == stamp) return false;
      seen_[s] = stamp;
      return static_cast<bool>(f(s));
    });
  }
  template <class F>
  void for_each_near(double min_x, double min_y, double max_x, double max_y, F&& f) const {
    (void)find_near(min_x, min_y, max_x, max_y, [&f](std::size_t s) {
      f(s);
      return false;
    });
  }

  // Doubles (proposals): the distance from p to the nearest segment closer than `cutoff`, with
  // that segment in `id`; `cutoff` (and id untouched) when none is closer.
  template <class P>
  [[nodiscard]] double nearest_closer_than(const P& point, double cutoff, std::uint32_t& id) const {
    const Point2<double> p = as_point(point);
    double best2 = cutoff * cutoff;
    for_each_near(p.x - cutoff, p.y - cutoff, p.x + cutoff, p.y + cutoff, [&](std::size_t s) {
      const double d2 = squared_distance(p, s);
      if (d2 < best2) {
        best2 = d2;
        id = static_cast<std::uint32_t>(s);
      }
    });
    return std::min(cutoff, std::sqrt(best2));
  }
  // The same distance alone.
  template <class P>
  [[nodiscard]] double distance(const P& point, double cutoff) const {
    std::uint32_t id = 0;
    return nearest_closer_than(point, cutoff, id);
  }

  // Doubles: some segment at distance <= radius from p (up to rounding).
  template <class P>
  [[nodiscard]] bool any_within(const P& point, double radius) const {
    const Point2<double> p = as_point(point);
    const double r2 = radius * radius;
    return visit_near(outward_box(p, radius),
                      [&](std::size_t s) { return squared_distance(p, s) <= r2; });
  }

  // Certified: false only when every segment is farther than radius from p, proven with
  // intervals (directed rounding): a selection that never misses.
  template <class P>
  [[nodiscard]] bool maybe_within(const P& point, double radius) const {
    const Point2<double> p = as_point(point);
    const GridBox box = outward_box(p, radius);
    const CGAL::Protect_FPU_rounding<true> rounding;
    const double r2 = CGAL::square(IntervalNT(radius)).sup();
    const IPoint ip{IntervalNT(p.x), IntervalNT(p.y)};
    return visit_near(box, [&](std::size_t s) {
      return squared_distance_enclosure(ip, enclose_end(source(segments_[s])),
                                        enclose_end(target(segments_[s])))
                 .inf() <= r2;
    });
  }

  // Certified prefilter: calls f(id) for every segment whose bounding box is not proven farther
  // than T (>= 0) from `box` (gaps rounded down, in the default rounding mode). Every segment
  // that f is not called for is farther than T from every point of the box.
  template <class F>
  void for_each_not_farther(const GridBox& box, double threshold, F&& f) const {
    const GridBox grown{next_down(box.lo_x - threshold), next_down(box.lo_y - threshold),
                        next_up(box.hi_x + threshold), next_up(box.hi_y + threshold)};
    // Diagonal test: gaps rounded to nearest then one ulp down are lower bounds; the squares'
    // sum rounded to nearest has a relative error below 2^-51, and so has T² above.
    const double need2 = threshold * threshold * (1.0 + 0x1p-50);
    for_each_near(grown.lo_x, grown.lo_y, grown.hi_x, grown.hi_y, [&](std::size_t k) {
      const Point2<double> a = source(segments_[k]), b = target(segments_[k]);
      const double gx0 = std::min(a.x, b.x), gx1 = std::max(a.x, b.x);
      const double gy0 = std::min(a.y, b.y), gy1 = std::max(a.y, b.y);
      if (gx0 > grown.hi_x || gx1 < grown.lo_x || gy0 > grown.hi_y || gy1 < grown.lo_y) return;
      const double bx = std::max(gap_below(gx0, box.hi_x), gap_below(box.lo_x, gx1));
      const double by = std::max(gap_below(gy0, box.hi_y), gap_below(box.lo_y, gy1));
      if ((bx * bx + by * by) * (1.0 - 0x1p-50) > need2) return;
      f(k);
    });
  }

  // Doubles (proposals): the distance from p to the nearest segment when it exceeds `floor`;
  // otherwise some value <= floor (the search stops at the first segment within floor), with in
  // `id` the segment that gave it. +inf without segments.
  template <class P>
  [[nodiscard]] double nearest_above(const P& p, double floor, std::uint32_t& id) const {
    return nearest(as_point(p), floor, id);
  }
  template <class P>
  [[nodiscard]] double nearest_above(const P& p, double floor) const {
    std::uint32_t id = 0;
    return nearest(as_point(p), floor, id);
  }

 private:
  // Any point type with double-convertible x and y (PointD, the fast engine's DPt, Point2).
  template <class P>
  static Point2<double> as_point(const P& p) {
    return {static_cast<double>(p.x), static_cast<double>(p.y)};
  }
  [[nodiscard]] double nearest(Point2<double> p, double floor, std::uint32_t& id) const;

  static IPoint enclose_end(Point2<double> p) { return {IntervalNT(p.x), IntervalNT(p.y)}; }

  [[nodiscard]] double squared_distance(Point2<double> p, std::size_t s) const {
    // The double path always decides a branch: the optional is never empty.
    return *squared_distance_to_segment(p, source(segments_[s]), target(segments_[s]));
  }

  // [p - radius, p + radius] with each bound rounded outwards (one ulp beyond nearest).
  static GridBox outward_box(Point2<double> p, double radius) {
    return {next_down(p.x - radius), next_down(p.y - radius), next_up(p.x + radius),
            next_up(p.y + radius)};
  }

  // The cell of v, unclamped (saturated far outside any grid).
  [[nodiscard]] std::int64_t cell_of(double v, double origin) const {
    const double c = std::floor((v - origin) / cell_);
    return static_cast<std::int64_t>(std::clamp(c, -1e15, 1e15));
  }
  // Cells [lo, hi], clamped into [0, n - 1], holding the exact cell floor((v - origin) / cell)
  // of v in every rounding mode. In any IEEE mode each of the two operations returns its exact
  // value times (1 + d) with |d| < 2^-52 (a subnormal difference is exact; a quotient that
  // underflows is off by less than 2^-1074), so the computed q and the exact t satisfy
  // |q - t| <= 2^-50 |t| + 2^-1074 <= 2^-49 |q| + 2^-1073. The slack |q| 2^-48 + 2^-1000 exceeds
  // that by more than the rounding of q -/+ slack (below 2^-51 |q| + 2^-1074 in any mode), so
  // floor(q - slack) <= floor(t) <= floor(q + slack). Clamping is monotone. A v whose q
  // overflows is beyond the grid's last cell (or before its first) in every mode.
  struct Span {
    int lo, hi;
  };
  [[nodiscard]] Span cell_span(double v, double origin, int n) const {
    const double q = (v - origin) / cell_;
    if (std::isnan(q)) return {0, n - 1}; // not a coordinate: every cell
    if (std::isinf(q)) return q > 0 ? Span{n - 1, n - 1} : Span{0, 0};
    const double slack = std::abs(q) * 0x1p-48 + 0x1p-1000;
    return {clamp_index(q - slack, n), clamp_index(q + slack, n)};
  }
  static int clamp_index(double q, int n) {
    if (!(q < static_cast<double>(n - 1))) return n - 1;
    return q > 0 ? static_cast<int>(std::floor(q)) : 0;
  }
  // The same cell to nearest (the fast engine's winding slabs, whose rows are filed and queried
  // with it in the default rounding mode).
  [[nodiscard]] int clamp_cell(double v, double origin, int n) const {
    const double c = std::floor((v - origin) / cell_);
    return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(n - 1)));
  }

  void build(double cell, std::size_t max_cells);

  std::vector<Segment> segments_;
  double origin_x_ = 0.0, origin_y_ = 0.0, cell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> cell_start_, cell_items_; // CSR: cell c lists items [start, start+1)
  mutable std::vector<std::uint64_t> seen_;            // find_near's once-only stamps
  mutable std::uint64_t stamp_ = 0;
};

template <class Segment, class Traits>
void SegmentGrid<Segment, Traits>::build(double cell, std::size_t max_cells) {
  if (segments_.empty()) return;
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  for (const Segment& s : segments_) {
    const Point2<double> a = source(s), b = target(s);
    min_x = std::min({min_x, a.x, b.x});
    max_x = std::max({max_x, a.x, b.x});
    min_y = std::min({min_y, a.y, b.y});
    max_y = std::max({max_y, a.y, b.y});
  }
  const double w = max_x - min_x, h = max_y - min_y;
  const auto budget = static_cast<double>(std::max<std::size_t>(max_cells, 1));
  // At most about max_cells cells in all and along either axis; never below a billionth of the
  // extent (the cell arithmetic must stay meaningful in doubles).
  cell_ = std::max(
      {cell, std::sqrt(w * h / budget), std::max(w, h) / budget, 1e-9 * std::max({w, h, 1.0})});
  origin_x_ = min_x;
  origin_y_ = min_y;
  nx_ = static_cast<int>(std::floor(w / cell_)) + 1;
  ny_ = static_cast<int>(std::floor(h / cell_)) + 1;

  // Two passes (count, fill) for compact bucket lists; each segment's cell range is computed
  // once, in the first (four divisions per segment: a third of a build).
  const std::size_t ncells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  cell_start_.assign(ncells + 1, 0);
  struct Range {
    int x0, x1, y0, y1;
  };
  std::vector<Range> ranges(segments_.size());
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const Point2<double> a = source(segments_[s]), b = target(segments_[s]);
    ranges[s] = {cell_span(std::min(a.x, b.x), origin_x_, nx_).lo,
                 cell_span(std::max(a.x, b.x), origin_x_, nx_).hi,
                 cell_span(std::min(a.y, b.y), origin_y_, ny_).lo,
                 cell_span(std::max(a.y, b.y), origin_y_, ny_).hi};
  }
  auto visit = [&](auto&& on_cell) {
    for (std::size_t s = 0; s < segments_.size(); ++s) {
      const Range& r = ranges[s];
      for (int gy = r.y0; gy <= r.y1; ++gy) {
        const std::size_t base = static_cast<std::size_t>(gy) * static_cast<std::size_t>(nx_);
        for (int gx = r.x0; gx <= r.x1; ++gx) on_cell(base + static_cast<std::size_t>(gx), s);
      }
    }
  };
  visit([&](std::size_t c, std::size_t) { ++cell_start_[c + 1]; });
  for (std::size_t c = 0; c < ncells; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_items_.resize(cell_start_.back());
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  visit([&](std::size_t c, std::size_t s) {
    cell_items_[fill[c]++] = static_cast<std::uint32_t>(s);
  });
}

template <class Segment, class Traits>
double SegmentGrid<Segment, Traits>::nearest(Point2<double> p, double floor,
                                             std::uint32_t& id) const {
  if (segments_.empty()) return std::numeric_limits<double>::infinity();
  const std::int64_t pc = cell_of(p.x, origin_x_), pr = cell_of(p.y, origin_y_);
  const std::int64_t nx = nx_, ny = ny_;
  // Rings of cells around p's cell: after ring k every segment not yet seen lies in cells at
  // least k + 1 cells away, so at least k cells' width from p: the search ends once the best
  // distance is within that.
  const std::int64_t last_ring = std::max({std::int64_t{0}, pc, nx - 1 - pc, pr, ny - 1 - pr});
  double best2 = std::numeric_limits<double>::infinity();
  const double floor2 = floor > 0 ? floor * floor : 0.0;
  auto visit = [&](std::int64_t r, std::int64_t c) {
    const auto cell = static_cast<std::size_t>(r * nx + c);
    for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
      const double d2 = squared_distance(p, cell_items_[k]);
      if (d2 < best2) {
        best2 = d2;
        id = cell_items_[k];
      }
      if (best2 <= floor2) return true;
    }
    return false;
  };
  // Rings that lie wholly outside the grid hold nothing: start at the first that meets it.
  const std::int64_t first_ring =
      std::max({std::int64_t{0}, -pc, pc - (nx - 1), -pr, pr - (ny - 1)});
  for (std::int64_t k = first_ring; k <= last_ring; ++k) {
    const std::int64_t c_lo = std::max<std::int64_t>(0, pc - k);
    const std::int64_t c_hi = std::min(nx - 1, pc + k);
    const std::int64_t r_lo = std::max<std::int64_t>(0, pr - k + 1);
    const std::int64_t r_hi = std::min(ny - 1, pr + k - 1);
    for (const std::int64_t r : {pr - k, pr + k}) {
      if (r < 0 || r >= ny) continue;
      for (std::int64_t c = c_lo; c <= c_hi; ++c) {
        if (visit(r, c)) return std::sqrt(best2);
      }
      if (k == 0) break; // ring 0 is one cell
    }
    for (const std::int64_t c : {pc - k, pc + k}) {
      if (k == 0 || c < 0 || c >= nx) continue;
      for (std::int64_t r = r_lo; r <= r_hi; ++r) {
        if (visit(r, c)) return std::sqrt(best2);
      }
    }
    const double reach = static_cast<double>(k) * cell_;
    if (best2 <= reach * reach) break;
  }
  return std::sqrt(best2);
}

} // namespace penshape::detail
