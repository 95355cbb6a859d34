// Ink-level Hausdorff certificate by 2-D grid sampling (argument in
// penshape/core/ink_certificate.hpp).
#include "recognize/certify/ink_certificate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/exact_double.hpp"
#include "recognize/certify/certified_distance.hpp"
#include "recognize/certify/ink_box_bounds.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
namespace {

using detail::enclose;
using detail::IntervalNT;
using Guard = CGAL::Protect_FPU_rounding<true>;

// The clean shape's distance function as the grid needs it, certified: an upper bound everywhere
// (for the Q side) and a test "is the true distance <= rho?" that never says no wrongly (for the
// clean-ink side). Doubles propose; the answers are interval bounds (certified_distance.hpp).
class ShapeDistance {
 public:
  ShapeDistance(const CleanShape& shape, double h) : shape_(shape), certified_(shape) {
    if (shape.kind == CleanShape::Kind::kCircle && !shape.full_curve()) prepare_arc();
    if (shape.kind != CleanShape::Kind::kEllipse) return;
    // The ellipse's chords through enclosed points at parameter steps dt: every point of the
    // ellipse is within speed dt / 2 of a true sample, which is within `reach` of its chord
    // vertex, so d(g, ellipse) >= d(g, chords) - slack_.
    const double speed = std::max(shape.rx, shape.ry);
    const double hs = std::max(h / 4.0, 2.0 * std::numbers::pi * speed / kMaxCurveSamples);
    const auto n =
        static_cast<std::size_t>(std::max(8.0, std::ceil(std::abs(shape.sweep) * speed / hs)));
    std::vector<PointD> pts;
    double reach = 0.0, step = 0.0, prev = shape.t0;
    for (std::size_t k = 0; k <= n; ++k) {
      const double t = shape.t0 + shape.sweep * static_cast<double>(k) / static_cast<double>(n);
      const detail::IPoint box = certified_.curve_point(t);
      const PointD v{0.5 * (box.x.inf() + box.x.sup()), 0.5 * (box.y.inf() + box.y.sup())};
      const Guard rounding;
      reach = std::max(reach, detail::distance_upper(box, enclose(v)));
      if (k > 0) {
        step =
            std::max(step, (IntervalNT(speed) * CGAL::abs(IntervalNT(t) - IntervalNT(prev))).sup());
      }
      prev = t;
      pts.push_back(v);
    }
    std::vector<Segment> chords;
    double half_chord = 0.0;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      chords.push_back({pts[i], pts[i + 1]});
      const Guard rounding;
      half_chord =
          std::max(half_chord, detail::distance_upper(enclose(pts[i]), enclose(pts[i + 1])) / 2.0);
    }
    chord_dev_ = sum_up({half_chord, reach}); // / 2 is exact
    chords_ = SegmentIndex(std::move(chords), 2.0 * h);
    slack_ = sum_up({step / 2.0, reach, certified_.end_slack()}); // step / 2 is exact
    cos_ = detail::enclose_cos(shape.rotation);
    sin_ = detail::enclose_sin(shape.rotation);
  }

  // >= d(x, C') for every x in the box, C' the curve with its end parameter rounded: polylines,
  // the least upper bound over every segment; arcs whose sector is known, the ray's distance or
  // the nearer end; full circles, the closed form; ellipses, the distance to the foot `near` (a
  // double point of the box) proposes, which refine() completes.
  [[nodiscard]] double upper(const detail::IPoint& box, PointD near) const {
    const CleanShape& s = shape_;
    if (arc_) return arc_upper(box);
    if (s.kind != CleanShape::Kind::kPolyline || s.path.size() < 2) {
      return certified_.upper(box, near);
    }
    const Guard rounding;
    double best = INFINITY;
    // The least over the segments of every piece (a jump between pieces is no segment).
    for (std::size_t i = 0; i + 1 < s.path.size(); ++i) {
      if (s.joined(i)) best = std::min(best, box_segment_upper(box, s.path[i], s.path[i + 1]));
    }
    return best;
  }
  // The value a grid point takes: upper() for all but ellipses, there the lesser of it and the
  // chords' bound (monotone, so that blocks can bound it). Only called when upper() alone would
  // raise the maximum: the value is at most upper(), so skipping it never changes the maximum.
  [[nodiscard]] double refine(const detail::IPoint& box, PointD near, double up) const {
    if (shape_.kind != CleanShape::Kind::kEllipse) return up;
    return std::min(up, chords_upper(box, near, true));
  }
  // >= refine(g, g, upper(g, g)) for every grid point g of the box, through a term of it monotone
  // in the box (ink_box_bounds.hpp); +inf when there is none (an arc whose sector is too near a
  // half turn to tell).
  [[nodiscard]] double block_upper(const detail::IPoint& box, PointD near) const {
    if (shape_.kind == CleanShape::Kind::kEllipse) return chords_upper(box, near, false);
    if (shape_.kind == CleanShape::Kind::kCircle && !shape_.full_curve() && !arc_) {
      return INFINITY;
    }
    return upper(box, near);
  }
  // >= H(C, C'): d(g, C) <= upper(g) + end_slack().
  [[nodiscard]] double end_slack() const { return certified_.end_slack(); }

  // False only when d(x, C) > rho for every x in the box, certainly; monotone in the box, so
  // false for a block means false for each of its grid points as computed there.
  [[nodiscard]] bool maybe_within(const detail::IPoint& box, double rho) const {
    const CleanShape& s = shape_;
    switch (s.kind) {
      case CleanShape::Kind::kPolyline:
        return polyline_maybe_within(box, rho);
      case CleanShape::Kind::kCircle: {
        // | |g - c| - R | <= d(g, arc) for any arc of the circle.
        const Guard rounding;
        const IntervalNT vx = box.x - IntervalNT(s.center.x);
        const IntervalNT vy = box.y - IntervalNT(s.center.y);
        const IntervalNT r = CGAL::sqrt(CGAL::square(vx) + CGAL::square(vy));
        double lower = CGAL::abs(r - IntervalNT(s.rx)).inf();
        // An arc, the box certainly outside its sector: the nearest point is an end.
        if (arc_ && outside_sector(vx, vy)) {
          const double to_ends = std::min(
              CGAL::sqrt(CGAL::square(box.x - end0_.x) + CGAL::square(box.y - end0_.y)).inf(),
              CGAL::sqrt(CGAL::square(box.x - end1_.x) + CGAL::square(box.y - end1_.y)).inf());
          lower = std::max(lower, to_ends);
        }
        // The true arc reaches at most end_slack beyond the one [t0, t0 + sweep] rounded gives.
        return lower <= sum_up({rho, certified_.end_slack()});
      }
      case CleanShape::Kind::kEllipse:
        break;
    }
    if (!ellipse_equation_allows(box, rho)) return false;
    const Guard rounding;
    return index_maybe_within(chords_, box, sum_up({rho, slack_}));
  }

 private:
  // The arc's ends and the directions of its bounding rays, enclosed; the sector is from u0_
  // counterclockwise to u1_ (ends swapped for a negative sweep), `wide_` when it exceeds a half
  // turn. Left unset (no sector test) when its span is too near a half turn to tell.
  void prepare_arc() {
    const CleanShape& s = shape_;
    const double te = s.t0 + s.sweep;
    const double from = s.sweep >= 0 ? s.t0 : te, to = s.sweep >= 0 ? te : s.t0;
    end0_ = certified_.curve_point(s.t0);
    end1_ = certified_.curve_point(te);
    u0_ = {detail::enclose_cos(from), detail::enclose_sin(from)};
    u1_ = {detail::enclose_cos(to), detail::enclose_sin(to)};
    const Guard rounding;
    const IntervalNT span = IntervalNT(to) - IntervalNT(from);
    const double pi_lo = std::numbers::pi, pi_hi = std::nextafter(std::numbers::pi, INFINITY);
    if (span.sup() < pi_lo) {
      arc_ = true;
      wide_ = false;
    } else if (span.inf() > pi_hi) {
      arc_ = true;
      wide_ = true;
    }
  }

  // >= d(x, C') over the box through the ellipse's chords: every point of a chord is within half
  // its length of a vertex, which is within `reach` of C' (monotone in the box).
  // `least`: the least bound over the chords (a grid point's value), else the nearest chord's (a
  // block's bound, which is above the least one of each of its points).
  [[nodiscard]] double chords_upper(const detail::IPoint& box, PointD near, bool least) const {
    const Guard rounding;
    const double d =
        least ? index_upper(chords_, box, near) : nearest_segment_upper(chords_, box, near);
    return sum_up({d, chord_dev_});
  }

  // An arc of C' (sector known): | |x - c| - R | when the box is certainly inside the sector
  // (the nearest point of the arc is then on x's ray), else the nearer end (an arc's point).
  [[nodiscard]] double arc_upper(const detail::IPoint& box) const {
    const Guard rounding;
    const IntervalNT vx = box.x - IntervalNT(shape_.center.x);
    const IntervalNT vy = box.y - IntervalNT(shape_.center.y);
    double best = std::min(detail::distance_upper(box, end0_), detail::distance_upper(box, end1_));
    const IntervalNT after_start = u0_.x * vy - u0_.y * vx;
    const IntervalNT before_end = vx * u1_.y - vy * u1_.x;
    const bool inside = wide_ ? after_start.inf() >= 0 || before_end.inf() >= 0
                              : after_start.inf() >= 0 && before_end.inf() >= 0;
    if (inside) {
      const IntervalNT r = CGAL::sqrt(CGAL::square(vx) + CGAL::square(vy));
      best = std::min(best, CGAL::abs(r - IntervalNT(shape_.rx)).sup());
    }
    return best;
  }

  // g - centre = (vx, vy) certainly outside the sector (caller holds the guard).
  [[nodiscard]] bool outside_sector(const IntervalNT& vx, const IntervalNT& vy) const {
    const IntervalNT after_start = u0_.x * vy - u0_.y * vx; // >= 0: counterclockwise of u0
    const IntervalNT before_end = vx * u1_.y - vy * u1_.x;  // >= 0: clockwise of u1
    if (wide_) return after_start.sup() < 0 && before_end.sup() < 0;
    return after_start.sup() < 0 || before_end.sup() < 0;
  }

  // Quick rejection: with F(p) = x^2/a^2 + y^2/b^2 - 1 (ellipse frame) and e the foot point,
  // |F(g)| = |F(g) - F(e)| <= d * max |grad F| over the disk of radius d around g. If d <= rho,
  // that max is <= 2 sqrt((|x| + rho)^2 / a^4 + (|y| + rho)^2 / b^4), so a larger |F(g)| / rho
  // proves d > rho. Evaluated in intervals: false only when certain.
  [[nodiscard]] bool ellipse_equation_allows(const detail::IPoint& g, double rho) const {
    const CleanShape& s = shape_;
    const Guard rounding;
    const IntervalNT dx = g.x - IntervalNT(s.center.x);
    const IntervalNT dy = g.y - IntervalNT(s.center.y);
    const IntervalNT x = CGAL::abs(cos_ * dx + sin_ * dy), y = CGAL::abs(cos_ * dy - sin_ * dx);
    const IntervalNT a2 = CGAL::square(IntervalNT(s.rx)), b2 = CGAL::square(IntervalNT(s.ry));
    const IntervalNT f = CGAL::abs(CGAL::square(x) / a2 + CGAL::square(y) / b2 - IntervalNT(1.0));
    const IntervalNT r(rho);
    const IntervalNT gx = (x + r) / a2, gy = (y + r) / b2;
    return f.inf() <= (IntervalNT(2.0) * r * CGAL::sqrt(CGAL::square(gx) + CGAL::square(gy))).sup();
  }

  // Each segment's box first (a coordinate gap rounded down bounds the distance below), then
  // the box-to-segment lower bound of the segments whose box is near (both monotone).
  [[nodiscard]] bool polyline_maybe_within(const detail::IPoint& g, double rho) const {
    const std::vector<PointD>& path = shape_.path;
    const Guard rounding;
    const double rho2 = CGAL::square(IntervalNT(rho)).sup();
    for (std::size_t i = 0; i + 1 < path.size() || (i == 0 && path.size() == 1); ++i) {
      if (path.size() > 1 && !shape_.joined(i)) continue; // a jump: near it is near no piece
      const PointD a = path[i], b = path.size() == 1 ? path[0] : path[i + 1];
      // -(x - lo) is lo - x rounded down (the guard rounds up).
      const double gap_x =
          std::max({-(g.x.sup() - std::min(a.x, b.x)), -(std::max(a.x, b.x) - g.x.inf()), 0.0});
      const double gap_y =
          std::max({-(g.y.sup() - std::min(a.y, b.y)), -(std::max(a.y, b.y) - g.y.inf()), 0.0});
      if (gap_x > rho || gap_y > rho) continue;
      if (box_segment_squared(g, a, b).lower <= rho2) return true;
    }
    return false;
  }

  const CleanShape& shape_;
  CertifiedShape certified_;
  SegmentIndex chords_{{}, 1.0};
  double slack_ = 0.0;
  double chord_dev_ = 0.0; // >= the distance from any point of the chords to C'
  IntervalNT cos_{1.0}, sin_{0.0};
  bool arc_ = false, wide_ = false;
  detail::IPoint end0_{}, end1_{}, u0_{}, u1_{};
};

// Where the row y crosses the edge [a, b] (a.y != b.y), enclosed.
RowCrossing crossing(PointD a, PointD b, double y) {
  const Guard rounding;
  const IntervalNT t = (IntervalNT(y) - IntervalNT(a.y)) / (IntervalNT(b.y) - IntervalNT(a.y));
  const IntervalNT x = IntervalNT(a.x) + t * (IntervalNT(b.x) - IntervalNT(a.x));
  return {x.inf(), x.sup()};
}

// Inside Q' along the row: 1 certainly inside, 0 certainly outside, -1 not certain (a crossing's
// interval holds x). `crossed` counts the crossings with lo < x so far (x increases).
int parity(const std::vector<RowCrossing>& xs, double widest, double x, std::size_t& crossed) {
  while (crossed < xs.size() && xs[crossed].lo < x) ++crossed;
  if (crossed < xs.size() && xs[crossed].lo <= x) return -1; // lo == x: it holds x
  // Crossings at lo >= x are right of x. Of those left of it, only the last few (lo within
  // `widest` of x) can reach x.
  for (std::size_t k = crossed; k-- > 0;) {
    if (xs[k].hi >= x) return -1;
    if (xs[k].lo < x - 2.0 * widest) break;
  }
  return static_cast<int>(crossed % 2);
}

// The rounding of Q's vertices: sup |v - to_double(v)| over the vertices, rounded up.
double vertex_rounding(const ExactPoint& v, PointD d) {
  if (detail::is_double_exactly(v.x) && detail::is_double_exactly(v.y)) return 0.0; // d is v
  const std::pair<double, double> x = CGAL::to_interval(v.x), y = CGAL::to_interval(v.y);
  const Guard rounding;
  const IntervalNT dx = CGAL::abs(IntervalNT(x.first, x.second) - IntervalNT(d.x));
  const IntervalNT dy = CGAL::abs(IntervalNT(y.first, y.second) - IntervalNT(d.y));
  return CGAL::sqrt(CGAL::square(dx) + CGAL::square(dy)).sup();
}

// One axis of the grid: the coordinates o + i h over i0..i1 (i0 lowered and i1 raised until
// they cover [lo, hi] exactly), and the widest gap between neighbours, rounded up.
std::vector<double> axis_lines(double o, double h, double lo, double hi, std::int64_t& first,
                               double& widest) {
  const auto line = [&](std::int64_t i) { return o + static_cast<double>(i) * h; };
  auto i0 = static_cast<std::int64_t>(std::floor((lo - o) / h));
  auto i1 = static_cast<std::int64_t>(std::ceil((hi - o) / h));
  while (line(i0) > lo) --i0;
  while (line(i1) < hi) ++i1;
  first = i0;
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(i1 - i0 + 1));
  for (std::int64_t i = i0; i <= i1; ++i) out.push_back(line(i));
  const Guard rounding;
  for (std::size_t k = 1; k < out.size(); ++k) {
    widest = std::max(widest, (IntervalNT(out[k]) - IntervalNT(out[k - 1])).sup());
  }
  return out;
}

// Grid point indices [i0, i1] x [j0, j1] (inclusive) into GridLines::x and y.
struct Block {
  std::size_t i0, i1, j0, j1;
};

// The two maxima over the grid (argument in penshape/core/ink_certificate.hpp): a point's
// selection and value are computed by eval() alone, the same whether the whole grid is visited
// (flat) or blocks are pruned; a block is skipped for a side only when its box proves, through
// bounds monotone in the box, that eval() would not select any of its points or that none of
// their values exceeds the maximum already reached over real grid points.
class GridScan {
 public:
  GridScan(const InkRegion& q, const ShapeDistance& shape, const GridLines& grid, double r)
      : q_(q),
        shape_(shape),
        grid_(grid),
        r_(r),
        rho_(sum_up({r, grid.reach})),
        near_q_(sum_up({grid.reach, q.rounding})) {}

  [[nodiscard]] double worst_clean() const { return worst_clean_; }
  [[nodiscard]] double worst_ink() const { return worst_ink_; }

  void flat() {
    for (std::size_t j = 0; j < grid_.y.size(); ++j) {
      for (std::size_t i = 0; i < grid_.x.size(); ++i) eval(i, j, true, true);
    }
  }

  // The grid as blocks of 16 x 16 points, then quadrants down to single points.
  void pruned() {
    std::vector<Scored> top;
    for (std::size_t j = 0; j < grid_.y.size(); j += kTop) {
      for (std::size_t i = 0; i < grid_.x.size(); i += kTop) {
        const Block b{i, std::min(i + kTop, grid_.x.size()) - 1, j,
                      std::min(j + kTop, grid_.y.size()) - 1};
        top.push_back(score(b, true, true));
      }
    }
    visit_all(top);
  }

 private:
  // Top blocks of kTop x kTop points; blocks at most kLeaf + 1 points wide are evaluated point
  // by point (scoring them would cost about as much as their points).
  static constexpr std::size_t kTop = 16;
  static constexpr std::size_t kLeaf = 2;
  // A block with what its box proves: whether a side may select a point of it, and an upper
  // bound on the values of that side's points (as eval() computes them).
  struct Scored {
    Block b;
    bool sel_clean, sel_ink;
    double up_clean, up_ink;
  };

  const std::vector<RowCrossing>& row(std::size_t j) const {
    static const std::vector<RowCrossing> kNoCrossings;
    // Q's crossings were computed on the same rows o.y + j h (prepare_ink).
    const std::int64_t k = grid_.first_j + static_cast<std::int64_t>(j) - q_.first_row;
    return k >= 0 && k < static_cast<std::int64_t>(q_.rows.size())
               ? q_.rows[static_cast<std::size_t>(k)]
               : kNoCrossings;
  }

  // One grid point, each side only when asked (a side not asked is proven not to matter).
  void eval(std::size_t i, std::size_t j, bool clean, bool ink) {
    const PointD g{grid_.x[i], grid_.y[j]};
    const detail::IPoint ig = enclose(g);
    const std::vector<RowCrossing>& xs = row(j);
    std::size_t crossed = static_cast<std::size_t>(
        std::partition_point(xs.begin(), xs.end(),
                             [&](const RowCrossing& c) { return c.lo < g.x; }) -
        xs.begin());
    const int inside = parity(xs, q_.widest, g.x, crossed);
    // Clean-ink side: d(g, Q') = 0 inside; else the least certified upper bound over Q's edges.
    // Any one edge's bound is above it: when that is not above the maximum, g cannot raise it.
    if (clean && inside != 1 && shape_.maybe_within(ig, rho_)) {
      std::uint32_t id = 0;
      (void)q_.edges.nearest_above(g, worst_clean_, id);
      const Guard rounding;
      const Segment& e = q_.edges.segment(id);
      if (box_segment_upper(ig, e.a, e.b) > worst_clean_) {
        worst_clean_ = std::max(worst_clean_, index_upper(q_.edges, ig, g));
      }
    }
    // Q side: inside Q', or possibly within near_q of its boundary.
    if (ink && (inside != 0 || within_q(ig))) {
      const double up = shape_.upper(ig, g);
      if (up > r_ && above_r(up) > worst_ink_) {
        const double dc = shape_.refine(ig, g, up);
        if (dc > r_) worst_ink_ = std::max(worst_ink_, above_r(dc));
      }
    }
  }

  [[nodiscard]] bool within_q(const detail::IPoint& box) const {
    const Guard rounding;
    return index_maybe_within(q_.edges, box, near_q_);
  }
  [[nodiscard]] double above_r(double dc) const {
    const Guard rounding;
    return (IntervalNT(dc) - IntervalNT(r_)).sup();
  }

  // What parity() finds at every grid point of the block: 0 (certainly outside Q') or 1
  // (certainly inside) at all of them, else -1: on each row no crossing's interval meets
  // [x0, x1] and the crossings left of x0 are even (odd) in number.
  [[nodiscard]] int block_parity(const Block& b) const {
    const double x0 = grid_.x[b.i0], x1 = grid_.x[b.i1];
    int found = -1;
    for (std::size_t j = b.j0; j <= b.j1; ++j) {
      const std::vector<RowCrossing>& xs = row(j);
      const auto left = std::partition_point(xs.begin(), xs.end(),
                                             [&](const RowCrossing& c) { return c.lo < x0; });
      const int side = static_cast<int>((left - xs.begin()) % 2);
      if (found != -1 && side != found) return -1;
      found = side;
      // parity() looks back only to crossings with lo >= x - 2 widest; none further reaches.
      auto k = std::partition_point(
          xs.begin(), left, [&](const RowCrossing& c) { return c.lo < x0 - 2.0 * q_.widest; });
      for (; k != xs.end() && k->lo <= x1; ++k) {
        if (k->hi >= x0) return -1;
      }
    }
    return found;
  }

  Scored score(const Block& b, bool clean, bool ink) const {
    const detail::IPoint box{IntervalNT(grid_.x[b.i0], grid_.x[b.i1]),
                             IntervalNT(grid_.y[b.j0], grid_.y[b.j1])};
    const PointD mid{grid_.x[(b.i0 + b.i1) / 2], grid_.y[(b.j0 + b.j1) / 2]};
    Scored s{b, false, false, 0.0, 0.0};
    const int inside = block_parity(b);
    s.sel_clean = clean && inside != 1 && shape_.maybe_within(box, rho_);
    if (s.sel_clean) {
      // Any one edge bounds the least upper bound eval() takes (ink_box_bounds.hpp).
      const Guard rounding;
      s.up_clean = nearest_segment_upper(q_.edges, box, mid);
    }
    s.sel_ink = ink && (inside != 0 || within_q(box));
    if (s.sel_ink) {
      const double dc = shape_.block_upper(box, mid);
      s.up_ink = dc > r_ ? above_r(dc) : 0.0;
    }
    return s;
  }

  // Blocks in decreasing order of how far they may raise a maximum (good maxima early).
  void visit_all(std::vector<Scored>& blocks) {
    constexpr double kNone = -std::numeric_limits<double>::infinity();
    const auto gain = [this](const Scored& s) {
      return std::max(s.sel_clean ? s.up_clean - worst_clean_ : kNone,
                      s.sel_ink ? s.up_ink - worst_ink_ : kNone);
    };
    std::sort(blocks.begin(), blocks.end(),
              [&](const Scored& a, const Scored& b) { return gain(a) > gain(b); });
    for (const Scored& s : blocks) visit(s);
  }

  // The block's sides still open (its bound above the maximum now reached), then its points or
  // its quadrants.
  void visit(const Scored& s) {
    const bool clean = s.sel_clean && s.up_clean > worst_clean_;
    const bool ink = s.sel_ink && s.up_ink > worst_ink_;
    if (!clean && !ink) return;
    const Block& b = s.b;
    if (b.i1 - b.i0 < kLeaf && b.j1 - b.j0 < kLeaf) {
      for (std::size_t j = b.j0; j <= b.j1; ++j) {
        for (std::size_t i = b.i0; i <= b.i1; ++i) eval(i, j, clean, ink);
      }
      return;
    }
    const std::size_t im = (b.i0 + b.i1) / 2, jm = (b.j0 + b.j1) / 2;
    std::vector<Scored> parts;
    for (const Block& c : {Block{b.i0, im, b.j0, jm}, Block{im + 1, b.i1, b.j0, jm},
                           Block{b.i0, im, jm + 1, b.j1}, Block{im + 1, b.i1, jm + 1, b.j1}}) {
      if (c.i0 <= c.i1 && c.j0 <= c.j1) parts.push_back(score(c, clean, ink));
    }
    visit_all(parts);
  }

  const InkRegion& q_;
  const ShapeDistance& shape_;
  const GridLines& grid_;
  double r_, rho_, near_q_;
  double worst_clean_ = 0.0; // >= max d(g, Q') over grid points standing for the clean ink
  double worst_ink_ = 0.0;   // >= max (d(g, C') - r) over grid points standing for Q
};

} // namespace

// The grid points are o + i h rounded (twice: the product, then the sum), so the gaps between
// neighbours are h only up to rounding, and how far they stray depends on the magnitudes of
// both i h and the sum (a bound from the largest coordinate alone fell short of the true gap).
// Instead of bounding the rounding, the gaps are measured: with the lines x_0 <= ... <= x_m and
// y_0 <= ... <= y_n (rounding is monotone), every point z of [x_0, x_m] x [y_0, y_n] lies in a
// cell [x_i, x_i+1] x [y_j, y_j+1] of sides a <= A and b <= B (A, B the widest gaps), and the
// nearest of that cell's corners is within sqrt(a^2 + b^2) / 2 <= sqrt(A^2 + B^2) / 2 of z.
GridLines grid_lines(PointD origin, double h, PointD lo, PointD hi) {
  GridLines g;
  double wx = 0.0, wy = 0.0;
  g.x = axis_lines(origin.x, h, lo.x, hi.x, g.first_i, wx);
  g.y = axis_lines(origin.y, h, lo.y, hi.y, g.first_j, wy);
  const Guard rounding;
  g.reach =
      (CGAL::sqrt(CGAL::square(IntervalNT(wx)) + CGAL::square(IntervalNT(wy))) / IntervalNT(2.0))
          .sup();
  return g;
}

InkRegion prepare_ink(const InkPolygon& ink, double epsilon) {
  if (ink.region.empty()) throw InvalidInput("ink certificate: the ink polygon is empty");
  if (!(epsilon > 0) || !std::isfinite(epsilon)) {
    throw InvalidInput("ink certificate: epsilon must be positive and finite");
  }
  InkRegion q;
  q.hausdorff_bound = ink.hausdorff_bound;
  std::vector<Segment> edges;
  q.lo = {INFINITY, INFINITY};
  q.hi = {-INFINITY, -INFINITY};
  std::vector<PointD> corners; // each vertex converted once
  auto add_ring = [&](const Ring& ring) {
    corners.clear();
    for (const ExactPoint& v : ring) {
      const PointD a = to_double(v);
      if (!std::isfinite(a.x) || !std::isfinite(a.y)) {
        throw InvalidInput("ink certificate: an ink polygon coordinate is not finite");
      }
      q.rounding = std::max(q.rounding, vertex_rounding(v, a));
      corners.push_back(a);
    }
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const PointD a = corners[i];
      edges.push_back({a, corners[(i + 1) % corners.size()]});
      q.lo = {std::min(q.lo.x, a.x), std::min(q.lo.y, a.y)};
      q.hi = {std::max(q.hi.x, a.x), std::max(q.hi.y, a.y)};
      q.magnitude = std::max({q.magnitude, std::abs(a.x), std::abs(a.y)});
    }
  };
  for (const PolygonWithHoles& p : ink.region.polygons) {
    add_ring(p.outer);
    for (const Ring& hole : p.holes) add_ring(hole);
  }
  if (edges.empty()) throw InvalidInput("ink certificate: the ink polygon has no edges");
  // Spacing: epsilon / 10, coarser when the sampled box (Q's box grown by about 1.3 epsilon on
  // each side, the most a certifiable shape's ink can reach) would exceed the point budget. The
  // spacing only sets the work: the half-diagonal added is the actual one.
  const double w = q.hi.x - q.lo.x + 2.6 * epsilon, ht = q.hi.y - q.lo.y + 2.6 * epsilon;
  q.h = std::max(epsilon / kInkGridDivisions, std::sqrt(w * ht / kMaxInkGridPoints));
  q.h = std::max(q.h, 1e-12 * std::max(w, ht));
  q.origin = q.lo;
  // Rows of the grid that meet Q's box, with where each edge crosses the row (half-open in y so
  // that a vertex on the row counts once for the two edges meeting there: exact comparisons of
  // doubles).
  q.first_row = static_cast<std::int64_t>(std::floor((q.lo.y - q.origin.y) / q.h));
  const auto last_row = static_cast<std::int64_t>(std::ceil((q.hi.y - q.origin.y) / q.h));
  q.rows.assign(static_cast<std::size_t>(last_row - q.first_row + 1), {});
  for (const Segment& e : edges) {
    const double ylo = std::min(e.a.y, e.b.y), yhi = std::max(e.a.y, e.b.y);
    if (ylo == yhi) continue;
    const auto j0 = static_cast<std::int64_t>(std::ceil((ylo - q.origin.y) / q.h)) - 1;
    const auto j1 = static_cast<std::int64_t>(std::floor((yhi - q.origin.y) / q.h)) + 1;
    for (std::int64_t j = std::max(j0, q.first_row); j <= std::min(j1, last_row); ++j) {
      const double y = q.origin.y + static_cast<double>(j) * q.h;
      if (y < ylo || y >= yhi) continue;
      const RowCrossing c = crossing(e.a, e.b, y);
      q.widest = std::max(q.widest, c.hi - c.lo);
      q.rows[static_cast<std::size_t>(j - q.first_row)].push_back(c);
    }
  }
  for (auto& row : q.rows) {
    std::sort(row.begin(), row.end(),
              [](const RowCrossing& a, const RowCrossing& b) { return a.lo < b.lo; });
  }
  q.edges = SegmentIndex(std::move(edges), 2.0 * q.h);
  return q;
}

Certificate certify_ink(const InkRegion& q, const CleanShape& shape, double epsilon,
                        double pen_radius, InkScan how) {
  Certificate cert;
  cert.method = "ink";
  cert.epsilon = epsilon;
  cert.pen_radius = pen_radius;
  const double h = q.h;
  cert.sample_spacing = h;
  const double r = pen_radius;

  // The clean ink's box (which grid points to visit; a proposal: points outside it are certainly
  // farther than rho from C only by the sampling argument, so the box is grown by a step more).
  double hs = 0.0;
  if (shape.kind != CleanShape::Kind::kPolyline) {
    const double length = std::abs(shape.sweep) * std::max(shape.rx, shape.ry);
    hs = std::max(h / 4.0, length / kMaxCurveSamples);
  }
  PointD lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  for (const PointD& p : hs > 0 ? shape.sample(hs) : shape.path) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const double grow = r + hs + h;
  lo = {lo.x - grow, lo.y - grow};
  hi = {hi.x + grow, hi.y + grow};
  const PointD ulo{std::min(lo.x, q.lo.x - h), std::min(lo.y, q.lo.y - h)};
  const PointD uhi{std::max(hi.x, q.hi.x + h), std::max(hi.y, q.hi.y + h)};
  const double extent = std::hypot(uhi.x - ulo.x, uhi.y - ulo.y);
  if (!std::isfinite(extent)) {
    cert.bound = INFINITY;
    return cert;
  }
  // A clean ink reaching more than epsilon + 3h beyond Q's box has a point farther than epsilon
  // from Q: it cannot certify (reported with the union box's diagonal, not a certificate).
  const double reach = epsilon + 3.0 * h;
  if (lo.x < q.lo.x - reach || lo.y < q.lo.y - reach || hi.x > q.hi.x + reach ||
      hi.y > q.hi.y + reach) {
    cert.bound = extent + q.hausdorff_bound;
    return cert;
  }

  const ShapeDistance to_shape(shape, h);
  // Grid points within half_diag of every point of the union box (grid_lines).
  const GridLines grid = grid_lines(q.origin, h, ulo, uhi);
  GridScan scan(q, to_shape, grid, r);
  if (how == InkScan::kFlat) {
    scan.flat();
  } else {
    scan.pruned();
  }
  const double half_diag = grid.reach;
  const double worst_clean = scan.worst_clean(), worst_ink = scan.worst_ink();
  // S2 was measured against C' (the curve's rounded end): H(C, C') <= end_slack is added.
  const double s2 = sum_up({worst_ink, to_shape.end_slack()});
  // H(C ⊕ D_r, T) <= H(C ⊕ D_r, Q') + H(Q', Q) + H(Q, T).
  cert.bound = sum_up({std::max(worst_clean, s2), half_diag, q.rounding, q.hausdorff_bound});
  cert.certified = std::isfinite(cert.bound) && cert.bound <= epsilon;
  return cert;
}

} // namespace penshape::recognize_detail

namespace penshape {

Certificate certify_ink(const InkPolygon& ink, ShapeClass shape, const ShapeParams& params,
                        double pen_radius, double epsilon) {
  if (!(pen_radius >= 0) || !std::isfinite(pen_radius)) {
    throw InvalidInput("ink certificate: the pen radius must be finite and >= 0");
  }
  const recognize_detail::CleanShape clean = recognize_detail::clean_shape_of(shape, params);
  const recognize_detail::InkRegion q = recognize_detail::prepare_ink(ink, epsilon);
  return recognize_detail::certify_ink(q, clean, epsilon, pen_radius);
}

} // namespace penshape
