// Certified predicates of the fast engine: intervals first, exact rationals when the interval
// cannot decide (certified.hpp).
#include "certified.hpp"

#include <CGAL/FPU.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/distance_kernel.hpp"
#include "geometry/exact_predicates.hpp"
#include "geometry/segment_grid.hpp"
#include "segment_index.hpp"

namespace penshape::fast {
namespace {

using detail::IntervalNT;
using detail::Point2;
using ExactPt = Point2<Rational>;
using IntervalPt = Point2<IntervalNT>;

thread_local std::uint64_t t_exact_fallbacks = 0;

template <typename NT>
Point2<NT> eval(const OnPiece& y) {
  const NT px(y.p.x), py(y.p.y);
  if (y.t == 0.0) return {px, py};
  const NT t(y.t);
  return {px + t * (NT(y.q.x) - px), py + t * (NT(y.q.y) - py)};
}

template <typename NT>
Point2<NT> eval(IPt p) {
  return {NT(static_cast<double>(p.x)), NT(static_cast<double>(p.y))};
}

// The point in doubles: for proposals only.
DPt eval_double(const OnPiece& y) {
  if (y.t == 0.0) return y.p;
  return {y.p.x + y.t * (y.q.x - y.p.x), y.p.y + y.t * (y.q.y - y.p.y)};
}

// sign(d(p, [s, t])² - T²) with intervals: 0 when undecided.
int interval_sign(const IntervalPt& p, const IntervalPt& s, const IntervalPt& t, double threshold) {
  const IntervalNT t2 = IntervalNT(threshold) * IntervalNT(threshold);
  const auto d2 = detail::squared_distance_to_segment(p, s, t);
  if (!d2) return 0;
  if (d2->sup() < t2.inf()) return -1;
  if (d2->inf() > t2.sup()) return 1;
  return 0;
}

int exact_sign(const ExactPt& p, const ExactPt& s, const ExactPt& t, double threshold) {
  ++t_exact_fallbacks;
  const Rational th(threshold);
  const int c = cmp(*detail::squared_distance_to_segment(p, s, t), th * th);
  return (c > 0) - (c < 0);
}

// The kernel's orientation determinant (geometry/exact_predicates.hpp) on Point2.
template <typename NT>
NT cross(const Point2<NT>& a, const Point2<NT>& b, const Point2<NT>& c) {
  return detail::orientation_determinant(a.x, a.y, b.x, b.y, c.x, c.y);
}

int sign_of(const IntervalNT& v) {
  if (v.inf() > 0) return 1;
  if (v.sup() < 0) return -1;
  return 0; // undecided (or zero)
}
int sign_of(const Rational& v) { return sgn(v) > 0 ? 1 : (sgn(v) < 0 ? -1 : 0); }

// Strict separation by one of the two lines and all four endpoint distances above T:
// 1 proven, -1 disproven, 0 undecided (intervals only; the exact version never returns 0).
template <typename NT, typename DistSign>
int separated_and_far(const Point2<NT>& y0, const Point2<NT>& y1, const Point2<NT>& a,
                      const Point2<NT>& b, double threshold, DistSign dist_sign) {
  const int s1 = sign_of(cross(a, b, y0)), s2 = sign_of(cross(a, b, y1));
  const int s3 = sign_of(cross(y0, y1, a)), s4 = sign_of(cross(y0, y1, b));
  const bool separated = s1 * s2 > 0 || s3 * s4 > 0;
  if (s1 * s2 < 0 && s3 * s4 < 0) return -1; // they cross
  int result = separated ? 1 : 0;
  for (const int s : {dist_sign(y0, a, b, threshold), dist_sign(y1, a, b, threshold),
                      dist_sign(a, y0, y1, threshold), dist_sign(b, y0, y1, threshold)}) {
    if (s < 0) return -1;
    if (s == 0) result = 0;
  }
  return result;
}

} // namespace

std::uint64_t exact_fallbacks() { return t_exact_fallbacks; }

int compare_distance(const OnPiece& y, IPt a, IPt b, double threshold) {
  {
    const UpwardRounding rounding;
    const int s =
        interval_sign(eval<IntervalNT>(y), eval<IntervalNT>(a), eval<IntervalNT>(b), threshold);
    if (s != 0) return s;
  }
  return exact_sign(eval<Rational>(y), eval<Rational>(a), eval<Rational>(b), threshold);
}

int compare_point_distance(const OnPiece& y, const OnPiece& z, double threshold) {
  {
    const UpwardRounding rounding;
    const IntervalPt u = eval<IntervalNT>(y);
    const int s = interval_sign(u, eval<IntervalNT>(z), eval<IntervalNT>(z), threshold);
    if (s != 0) return s;
  }
  const ExactPt v = eval<Rational>(z);
  return exact_sign(eval<Rational>(y), v, v, threshold);
}

bool segments_farther_than(const OnPiece& y0, const OnPiece& y1, IPt a, IPt b, double threshold) {
  {
    const UpwardRounding rounding;
    const int s = separated_and_far(eval<IntervalNT>(y0), eval<IntervalNT>(y1), eval<IntervalNT>(a),
                                    eval<IntervalNT>(b), threshold, &interval_sign);
    if (s != 0) return s > 0;
  }
  // Exact: a zero orientation means "not strictly separated", a zero distance sign "not above".
  ++t_exact_fallbacks;
  return separated_and_far(eval<Rational>(y0), eval<Rational>(y1), eval<Rational>(a),
                           eval<Rational>(b), threshold, &exact_sign) > 0;
}

namespace {

// The box of two enclosures: it contains every point they enclose.
Box box_of(const IntervalPt& a, const IntervalPt& b) {
  return {std::min(a.x.inf(), b.x.inf()), std::min(a.y.inf(), b.y.inf()),
          std::max(a.x.sup(), b.x.sup()), std::max(a.y.sup(), b.y.sup())};
}

} // namespace

Box enclosing_box(const OnPiece& y0, const OnPiece& y1) {
  const UpwardRounding rounding;
  return box_of(eval<IntervalNT>(y0), eval<IntervalNT>(y1));
}

// A sum rounded to nearest is within half an ulp of the exact value: one ulp outwards bounds
// it without switching the rounding mode.
double add_up(double a, double b) { return detail::next_up(a + b); }

double sub_down(double a, double b) { return detail::next_down(a - b); }

namespace {

// The edges of the index whose boxes are not proven farther than T from the box of y0, y1 (the
// grid's certified prefilter, segment_grid.hpp), in a buffer reused by the thread (callers
// consume it before the next call).
const std::vector<std::size_t>& edges_near(const SegmentIndex& index, const Box& box,
                                           double threshold) {
  thread_local std::vector<std::size_t> out;
  out.clear();
  index.grid().for_each_not_farther({box.lo_x, box.lo_y, box.hi_x, box.hi_y}, threshold,
                                    [&](std::size_t k) { out.push_back(k); });
  return out;
}

} // namespace

namespace {

// An upper bound on the distance between any two points of the enclosures a and b (requires
// upward rounding; the root passes CGAL's opaque barrier, so it stays inside the scope).
double distance_up(const IntervalPt& a, const IntervalPt& b) {
  const IntervalNT dx = b.x - a.x, dy = b.y - a.y;
  return CGAL::IA_opacify(std::sqrt(CGAL::IA_opacify((dx * dx + dy * dy).sup())));
}

} // namespace

bool piece_farther_than(const SegmentIndex& index, const OnPiece& y0, const OnPiece& y1,
                        double threshold) {
  // The ends' enclosures once: their box for the grid's prefilter (which runs in the default
  // rounding mode), then the intervals of every near edge under one more switch; the exact
  // fallback after it.
  IntervalPt i0{}, i1{}, mid{};
  double reach = 0.0; // T + half the piece's length, rounded up
  {
    const UpwardRounding rounding;
    i0 = eval<IntervalNT>(y0);
    i1 = eval<IntervalNT>(y1);
    mid = {(i0.x + i1.x) / 2, (i0.y + i1.y) / 2};
    reach = (IntervalNT(threshold) + IntervalNT(distance_up(i0, i1)) / 2).sup();
  }
  const std::vector<std::size_t>& near = edges_near(index, box_of(i0, i1), threshold);
  std::vector<std::size_t> undecided;
  {
    const UpwardRounding rounding;
    for (const std::size_t k : near) {
      const Segment& g = index.segments()[k];
      const IntervalPt a = eval<IntervalNT>(g.a), b = eval<IntervalNT>(g.b);
      // Every point of the piece is within half its length of the midpoint: an edge farther
      // than T + that from the midpoint is farther than T from the piece (one distance
      // instead of four and four orientations; most near edges are that far).
      if (interval_sign(mid, a, b, reach) > 0) continue;
      const int s = separated_and_far(i0, i1, a, b, threshold, &interval_sign);
      if (s < 0) return false;
      if (s == 0) undecided.push_back(k);
    }
  }
  for (const std::size_t k : undecided) {
    const Segment& g = index.segments()[k];
    ++t_exact_fallbacks;
    if (separated_and_far(eval<Rational>(y0), eval<Rational>(y1), eval<Rational>(g.a),
                          eval<Rational>(g.b), threshold, &exact_sign) <= 0) {
      return false;
    }
  }
  return true;
}

bool all_edges_farther(const SegmentIndex& index, const OnPiece& y, double threshold) {
  IntervalPt iy{};
  {
    const UpwardRounding rounding;
    iy = eval<IntervalNT>(y);
  }
  const std::vector<std::size_t>& near = edges_near(index, box_of(iy, iy), threshold);
  std::vector<std::size_t> undecided;
  {
    const UpwardRounding rounding;
    for (const std::size_t k : near) {
      const Segment& g = index.segments()[k];
      const int s = interval_sign(iy, eval<IntervalNT>(g.a), eval<IntervalNT>(g.b), threshold);
      if (s < 0) return false;
      if (s == 0) undecided.push_back(k);
    }
  }
  for (const std::size_t k : undecided) {
    const Segment& g = index.segments()[k];
    if (exact_sign(eval<Rational>(y), eval<Rational>(g.a), eval<Rational>(g.b), threshold) <= 0) {
      return false;
    }
  }
  return true;
}

bool some_edge_closer(const SegmentIndex& index, const OnPiece& y, double threshold,
                      std::size_t* hint) {
  if (threshold <= 0.0) return false;
  // The caller's hint first: the edge that proved its last question often proves this one.
  if (hint != nullptr && *hint < index.segments().size()) {
    const Segment& g = index.segments()[*hint];
    if (closer_than(y, g.a, g.b, threshold)) return true;
  }
  const DPt approx = eval_double(y);
  // Doubles propose: an edge clearly closer (by a sixteenth) is certified at once; otherwise
  // the nearest edge found is.
  const double clear = threshold * (15.0 / 16.0);
  std::size_t best = index.segments().size(); // none
  double best_d = threshold + 1.0;
  const double reach = best_d;
  const auto closer = [&](std::size_t k) {
    const Segment& g = index.segments()[k];
    return closer_than(y, g.a, g.b, threshold);
  };
  const bool early = index.find_near(
      approx.x - reach, approx.y - reach, approx.x + reach, approx.y + reach, [&](std::size_t k) {
        const Segment& g = index.segments()[k];
        const double d = point_segment_distance(approx, g.da(), g.db());
        if (d < best_d) {
          best_d = d;
          best = k;
        }
        return d < clear && closer(k);
      });
  // When `early`, the edge that proved it is the nearest so far (a nearer one below `clear`
  // would have proved it first).
  const bool found = early || (best < index.segments().size() && best_d >= clear && closer(best));
  if (found && hint != nullptr) *hint = best;
  return found;
}

} // namespace penshape::fast
