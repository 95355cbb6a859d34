#include "level_set_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

#include "arc_turns.hpp"
#include "certified.hpp"
#include "geometry/distance_kernel.hpp"
#include "geometry/exact_predicates.hpp"
#include "geometry/segment_grid.hpp"
#include "geometry/segment_sweep.hpp"

namespace penshape::fast {
namespace {

using detail::IntervalNT;

// Arc chords are refined down to this sagitta (grid units) before a piece counts as not
// verified. It only limits the work spent on a piece; soundness rests on the derived errors.
constexpr double kMinSagitta = 0.5;
// A piece that is neither deep nor far from B as a whole is tried in halves, each of them in
// halves again down to eighths, before the cover test (which asks every near edge of A and B):
// on KAZ's decision 149 of 1,508 pieces need more than the whole-piece tests, and the parts
// settle most of them (the level-set walk 1.05 -> 0.91 ms; deeper splits gain nothing more). A
// work limit only: each part is decided by the same certified tests.
constexpr int kSplitDepth = 2;
// Arcs are first walked with chords of this many times max_sagitta, then each chord that fails
// is halved (coarse to fine): most chords of a level set are deep or far from B and pass at
// once (KAZ's decision: 7% less time; the 200,000-vertex star: the same). Completeness rests on
// kMinSagitta, soundness on each chord's derived error, so neither changes.
constexpr double kFirstChordFactor = 4.0;

struct Interval {
  double lo;
  double hi;
};

// A piece of the walked curve: the exact segment between the double points p and q, with a
// certified bound: every curve point it stands for lies within `error` of some point of the
// piece (derived with outward rounding in Walker::ends / arc_piece below).
struct Piece {
  DPt p;
  DPt q;
  double error = 0.0;
};

DPt at(const Piece& s, double t) {
  return {s.p.x + t * (s.q.x - s.p.x), s.p.y + t * (s.q.y - s.p.y)};
}
OnPiece on(const Piece& s, double t) { return {s.p, s.q, t}; }

// Solves k0 + k1 t in [lo, hi] for t; returns false when empty.
bool linear_range(double k0, double k1, double lo, double hi, Interval& out) {
  if (k1 == 0.0) {
    if (k0 < lo || k0 > hi) return false;
    out = {-1e300, 1e300};
    return true;
  }
  double t0 = (lo - k0) / k1;
  double t1 = (hi - k0) / k1;
  if (t0 > t1) std::swap(t0, t1);
  out = {t0, t1};
  return true;
}

// Parameters t with d(y(t), [a, b]) <= radius, as a hint computed in double (callers verify or
// inflate): the hull of the two end-disk intervals and the slab interval (the stadium is convex).
bool stadium_interval(const Piece& s, DPt a, DPt b, double radius, Interval& out) {
  const double dx = s.q.x - s.p.x, dy = s.q.y - s.p.y;
  bool any = false;
  Interval hull{1e300, -1e300};
  auto add = [&](Interval iv) {
    if (iv.lo > iv.hi) return;
    hull.lo = std::min(hull.lo, iv.lo);
    hull.hi = std::max(hull.hi, iv.hi);
    any = true;
  };
  const double alpha = dx * dx + dy * dy;
  for (const DPt& c : {a, b}) {
    const double wx = s.p.x - c.x, wy = s.p.y - c.y;
    const double beta = dx * wx + dy * wy;
    const double gamma = wx * wx + wy * wy - radius * radius;
    if (alpha == 0.0) {
      if (gamma <= 0.0) add({-1e300, 1e300});
      continue;
    }
    const double disc = beta * beta - alpha * gamma;
    if (disc < 0.0) continue;
    const double sq = std::sqrt(disc);
    add({(-beta - sq) / alpha, (-beta + sq) / alpha});
  }
  const double ux = b.x - a.x, uy = b.y - a.y;
  const double len2 = ux * ux + uy * uy;
  if (len2 > 0.0) {
    const double wx = s.p.x - a.x, wy = s.p.y - a.y;
    Interval along{}, across{};
    if (linear_range(wx * ux + wy * uy, dx * ux + dy * uy, 0.0, len2, along) &&
        linear_range(ux * wy - uy * wx, ux * dy - uy * dx, -radius * std::sqrt(len2),
                     radius * std::sqrt(len2), across)) {
      add({std::max(along.lo, across.lo), std::min(along.hi, across.hi)});
    }
  }
  if (!any) return false;
  out = {std::max(hull.lo, 0.0), std::min(hull.hi, 1.0)};
  return out.lo <= out.hi;
}

IPt round_point(DPt p) { return {std::llround(p.x), std::llround(p.y)}; }

// sqrt of an interval under upward rounding without switching modes (CGAL::sqrt switches to
// downward and back for the lower end): the upward-rounded root of the upper end bounds it
// from above; the upward-rounded root of the lower end exceeds the true one by less than an
// ulp, so one ulp down bounds it from below. The roots' operands and results pass through
// CGAL's opaque barrier (as every Interval_nt operation does), so the compiler cannot move the
// square roots out of the caller's UpwardRounding scope.
IntervalNT sqrt_upward(const IntervalNT& v) {
  const double lo =
      v.inf() > 0 ? detail::next_down(CGAL::IA_opacify(std::sqrt(CGAL::IA_opacify(v.inf())))) : 0.0;
  return {lo, CGAL::IA_opacify(std::sqrt(CGAL::IA_opacify(v.sup())))};
}

// The exact unit vector u / |u| enclosed in intervals (requires upward rounding).
detail::IPoint unit(DPt u) {
  const IntervalNT ux(u.x), uy(u.y);
  const IntervalNT len = sqrt_upward(ux * ux + uy * uy);
  return {ux / len, uy / len};
}

// The exact point c + L n enclosed in intervals, n a unit vector's enclosure.
detail::IPoint on_circle(IPt c, const detail::IPoint& n, double level) {
  const IntervalNT l(level);
  return {IntervalNT(static_cast<double>(c.x)) + l * n.x,
          IntervalNT(static_cast<double>(c.y)) + l * n.y};
}

// A double inside the enclosure and an upper bound on its distance to every point of it
// (requires upward rounding: interval operations, which the compiler keeps inside the scope).
DPt represent(const detail::IPoint& e, double& deviation) {
  const DPt p{e.x.inf(), e.y.inf()};
  const IntervalNT dx = IntervalNT(e.x.sup()) - IntervalNT(p.x);
  const IntervalNT dy = IntervalNT(e.y.sup()) - IntervalNT(p.y);
  deviation = sqrt_upward(dx * dx + dy * dy).sup();
  return p;
}

// Upper bound on the sagitta L (1 - cos(phi/2)) of the arc between the directions u and w
// (angle phi < pi), requires upward rounding. With c = |u/|u| - w/|w|| the unit chord,
// 1 - cos(phi/2) = (c²/4) / (1 + sqrt(1 - c²/4)) <= c² / (8 - c²) (as sqrt(x) >= x on [0, 1]),
// and when u·w >= 0 (phi <= pi/2), c² = 2 (1 - cos phi) = 2 sin² phi / (1 + cos phi)
// <= 2 sin² phi / (1 + cos² phi) = 2 (u x w)² / (|u|² |w|² + (u·w)²) (cos >= cos² on [0, 1]):
// no square root, no cancellation, tight for small angles. Otherwise c² from unit vectors.
double sagitta_bound(DPt u, DPt w, double level) {
  const IntervalNT ux(u.x), uy(u.y), wx(w.x), wy(w.y);
  const IntervalNT uu = ux * ux + uy * uy, ww = wx * wx + wy * wy;
  const IntervalNT dot = ux * wx + uy * wy;
  IntervalNT c2;
  if (dot.inf() >= 0) {
    const IntervalNT cr = ux * wy - uy * wx;
    c2 = 2 * (cr * cr) / (uu * ww + dot * dot);
  } else {
    const IntervalNT lu = sqrt_upward(uu), lw = sqrt_upward(ww);
    const IntervalNT cx = ux / lu - wx / lw, cy = uy / lu - wy / lw;
    c2 = cx * cx + cy * cy;
  }
  if (c2.sup() >= 4) return level; // a half turn at most moves L
  return (IntervalNT(level) * c2 / (8 - c2)).sup();
}

class Walker {
 public:
  Walker(const LevelSetQuery& q, const CancelHook& cancel)
      : q_(q),
        cancel_(cancel),
        memo_(q.memo != nullptr && q.memo->serves(q.a, q.level, q.max_sagitta) ? q.memo : nullptr) {
  }

  bool run() {
    const IRings& rings = q_.a->rings();
    std::size_t base = 0; // index of the ring's first vertex among all of A's (the memo's)
    for (const IRing& ring : rings) {
      const std::size_t n = ring.size();
      base += n;
      ends(ring);
      for (std::size_t i = 0; i < n; ++i) {
        const IPt prev = ring[(i + n - 1) % n];
        const IPt v = ring[i];
        const IPt next = ring[(i + 1) % n];
        const std::size_t vertex = base - n + i;
        // The arc around v first, from in_[i] to out_[i], then the offset segment of edge
        // v -> next from out_[i] to in_[i + 1]: in the level set's order, so that each piece
        // starts where the one before ended (continues_clear). Every point of the arc is within
        // `level` of v (and its chords too).
        if (orientation(prev, v, next) > 0 && !outside_window(to_d(v), to_d(v), q_.level) &&
            !arc(prev, v, next, in_[i], out_[i], vertex)) {
          return false;
        }
        // Every point of the true segment is within the larger deviation of the piece
        // (convexity).
        const Rep& p = out_[i];
        const Rep& q = in_[(i + 1) % n];
        const double dev = std::max(p.dev, q.dev);
        if (!outside_window(p.p, q.p, dev) && !check({p.p, q.p, dev}, {vertex, 0})) return false;
        if ((++pieces_ & 255U) == 0 && cancel_ && cancel_()) throw Cancelled();
      }
    }
    return true;
  }

 private:
  // Whether every point within `reach` of the segment [p, q] is outside the query's window (two
  // units spare cover the rounding of these double sums; false without a window).
  [[nodiscard]] bool outside_window(DPt p, DPt q, double reach) const {
    if (q_.window == nullptr) return false;
    const Window& w = *q_.window;
    const double r = reach + 2.0;
    return std::min(p.x, q.x) - r > w.hi_x || std::max(p.x, q.x) + r < w.lo_x ||
           std::min(p.y, q.y) - r > w.hi_y || std::max(p.y, q.y) + r < w.lo_y;
  }

  // A double standing for an exact point of the level set, and its proven distance to it.
  struct Rep {
    DPt p;
    double dev = 0.0;
  };

  // The right normal direction of a -> b, exact (integer differences, |.| <= 2^32).
  static DPt right_direction(IPt a, IPt b) {
    return {static_cast<double>(b.y - a.y), -static_cast<double>(b.x - a.x)};
  }

  static Rep rep(IPt c, DPt u, double level) {
    Rep r{};
    r.p = represent(on_circle(c, unit(u), level), r.dev);
    return r;
  }

  // For every vertex v_i of the ring, the exact points v_i + L n of the normals of its incoming
  // (in_) and outgoing (out_) edges, enclosed in intervals under one rounding-mode switch: the
  // ends of the straight pieces and of the arcs.
  void ends(const IRing& ring) {
    const std::size_t n = ring.size();
    in_.resize(n);
    out_.resize(n);
    const UpwardRounding rounding;
    for (std::size_t i = 0; i < n; ++i) {
      // Edge i -> i + 1: one unit normal for both of its ends.
      const IPt a = ring[i], b = ring[(i + 1) % n];
      const detail::IPoint normal = unit(right_direction(a, b));
      out_[i].p = represent(on_circle(a, normal, q_.level), out_[i].dev);
      Rep& end = in_[(i + 1) % n];
      end.p = represent(on_circle(b, normal, q_.level), end.dev);
    }
  }

  // The arc of radius `level` around a convex vertex v, from the right normal u0 of (prev, v)
  // to u1 of (v, next), counterclockwise, as chords of sagitta about max_sagitta.
  bool arc(IPt prev, IPt v, IPt next, const Rep& start, const Rep& end, std::size_t vertex) {
    const DPt u0 = right_direction(prev, v);
    const DPt u1 = right_direction(v, next);
    const double a0 = std::atan2(u0.y, u0.x);
    double sweep = std::atan2(u1.y, u1.x) - a0;
    while (sweep < 0.0) sweep += 2.0 * M_PI;
    while (sweep >= 2.0 * M_PI) sweep -= 2.0 * M_PI;
    const double first = kFirstChordFactor * q_.max_sagitta;
    const double max_half = std::acos(std::max(0.0, 1.0 - first / q_.level));
    const int m = std::max(1, static_cast<int>(std::ceil(sweep / (2.0 * max_half))));
    const double step = sweep / m;
    Dir from{u0, start, true};
    for (int k = 0; k < m; ++k) {
      const double angle = a0 + step * (k + 1);
      Dir to{u1, end, true};
      if (k + 1 < m) {
        to.u = {std::cos(angle), std::sin(angle)};
        to.exact_end = false;
        const UpwardRounding rounding;
        to.rep = rep(v, to.u, q_.level);
      }
      const auto bit = static_cast<unsigned>(k + 1);
      const Slot slot = bit < LevelSetMemo::kEntries ? Slot{vertex, bit} : Slot{};
      if (!arc_piece(v, from, to, a0 + step * k, angle, u0, u1, slot)) return false;
      from = to;
    }
    return true;
  }

  // A top-level piece's entry in the memo (LevelSetMemo); kNoSlot for split chords.
  static constexpr unsigned kNoSlot = LevelSetMemo::kEntries;
  struct Slot {
    std::size_t vertex = 0;
    unsigned bit = kNoSlot;
  };

  // A direction of the arc: an end normal (exact_end) or a proposed one, with its point.
  struct Dir {
    DPt u;
    Rep rep;
    bool exact_end = false;
  };

  // The sub-arc between directions `from` and `to` (angles given as hints for splitting). The
  // chords cover the arc from u0 to u1 when every direction lies in that cone (< pi, the vertex
  // is convex) and consecutive directions turn counterclockwise: checked exactly (the end
  // normals are in the cone and in order by convexity), else the piece is not verified.
  // Error = sagitta bound + the endpoints' deviations, rounded up.
  bool arc_piece(IPt c, const Dir& from, const Dir& to, double a_from, double a_to, DPt u0, DPt u1,
                 Slot slot) {
    // The turns that make the chords cover the arc (arc_turns.hpp), their interval signs and
    // the chord's error under one rounding switch; a turn the intervals cannot tell is decided
    // exactly after it. A clockwise turn fails the piece.
    ArcTurns turns(u0, u1, from.u, from.exact_end, to.u, to.exact_end);
    Piece piece{};
    double sagitta = 0.0;
    {
      const UpwardRounding rounding;
      turns.sign_by_intervals();
      piece.p = from.rep.p;
      piece.q = to.rep.p;
      sagitta = sagitta_bound(from.u, to.u, q_.level);
      piece.error = (IntervalNT(sagitta) + IntervalNT(std::max(from.rep.dev, to.rep.dev))).sup();
    }
    if (!turns.counterclockwise()) return false;
    if (check(piece, slot)) return true;
    if (sagitta < kMinSagitta) return false;
    const double mid = 0.5 * (a_from + a_to);
    Dir m{{std::cos(mid), std::sin(mid)}, {}, false};
    {
      const UpwardRounding rounding;
      m.rep = rep(c, m.u, q_.level);
    }
    return arc_piece(c, from, m, a_from, mid, u0, u1, {}) &&
           arc_piece(c, m, to, mid, a_to, u0, u1, {});
  }

  // The sub-piece [t0, t1] lies in the open exterior of B: its rounded midpoint has winding 0
  // and is proven closer to the sub-piece than the sub-piece's proven distance to ∂B (`need`,
  // checked by the caller), so the segment joining them does not meet ∂B.
  bool outside_b(const Piece& s, double t0, double t1, double need) const {
    const double tm = 0.5 * (t0 + t1);
    const IPt z = round_point(at(s, tm));
    if (q_.b->winding(z) > 0) return false;
    return compare_point_distance(on(s, tm), at_point(z), need) < 0;
  }

  // Proven d([y(t0), y(t1)], ∂B) > need (certified.hpp).
  bool far_from_b(const Piece& s, double t0, double t1, double need) {
    return piece_farther_than(*q_.b, on(s, t0), on(s, t1), need);
  }

  // Lower bound on L - half - error for the deep test of the part [t0, t1] of the piece
  // (half: half the part's length, t1 - t0 exact), rounded down.
  double deep_threshold(const Piece& s, double t0 = 0.0, double t1 = 1.0) const {
    const UpwardRounding rounding;
    const IntervalNT dx = IntervalNT(s.q.x) - IntervalNT(s.p.x);
    const IntervalNT dy = IntervalNT(s.q.y) - IntervalNT(s.p.y);
    const IntervalNT half = sqrt_upward(dx * dx + dy * dy) * IntervalNT(t1 - t0) / 2;
    return (IntervalNT(q_.level) - half - IntervalNT(s.error)).inf();
  }

  // The part [t0, t1] of the piece passes the cheap tests of check(): deep, or far from B and
  // outside it; else its halves do, down to `depth` halvings. Parameters are dyadic, so every
  // midpoint and difference is exact.
  bool part_passes(const Piece& s, double t0, double t1, double need, int depth) {
    const double tm = 0.5 * (t0 + t1);
    if (some_edge_closer(*q_.a, on(s, tm), deep_threshold(s, t0, t1), &last_deep_)) return true;
    if (far_from_b(s, t0, t1, need) && outside_b(s, t0, t1, need)) return true;
    return depth > 0 && part_passes(s, t0, tm, need, depth - 1) &&
           part_passes(s, tm, t1, need, depth - 1);
  }

  // Deep inside {d(·, A) < level}: every piece point is within half its length of the
  // midpoint and every curve point within `error` of the piece (1-Lipschitz). The memo's answer
  // when it has one for this piece (the same test on the same piece, see LevelSetMemo).
  bool deep(const Piece& s, Slot slot) {
    LevelSetMemo* memo = slot.bit == kNoSlot ? nullptr : memo_;
    if (memo != nullptr && memo->known(slot.vertex, slot.bit)) {
      return memo->deep(slot.vertex, slot.bit);
    }
    const bool is_deep = some_edge_closer(*q_.a, on(s, 0.5), deep_threshold(s), &last_deep_);
    if (memo != nullptr) memo->record(slot.vertex, slot.bit, is_deep);
    return is_deep;
  }

  // check_piece, remembering where a piece proven clear of B (far from it and outside it) ends.
  bool check(const Piece& s, Slot slot) {
    bool clear = false;
    const bool passed = check_piece(s, slot, clear);
    clear_end_ = clear ? std::optional<DPt>(s.q) : std::nullopt;
    return passed;
  }

  // A piece far from B that starts exactly where the last piece proven clear of B ended is
  // outside B too: the two are connected, the earlier one lies in B's open exterior and the new
  // one never meets ∂B. Consecutive pieces of the walk share their end points (the straight
  // pieces and the arcs' chords are built from the same represented points), so a run of far
  // pieces needs one winding number, not one each.
  [[nodiscard]] bool continues_clear(const Piece& s) const {
    return clear_end_ && clear_end_->x == s.p.x && clear_end_->y == s.p.y;
  }

  bool check_piece(const Piece& s, Slot slot, bool& clear) {
    // Distance every represented curve point must keep from B's edges: clearance + error.
    const double need = add_up(q_.clearance, s.error);
    // The piece passes when it is deep or when it is far from B and outside it; either order
    // gives the same answer (and `far` the same value below). Deep first by default: most
    // offset segments of a jagged A are, and this asks one edge, not all of B's near ones. But
    // a piece that continues a run of pieces clear of B most likely lies on the level set too,
    // where the deep test fails only after asking every near edge: the clear test first then
    // (it needs no winding number there; KAZ's decision 2%).
    const bool clear_first = q_.clear_first || continues_clear(s);
    if (!clear_first && deep(s, slot)) return true;
    const bool far = far_from_b(s, 0.0, 1.0, need);
    if (far && (continues_clear(s) || outside_b(s, 0.0, 1.0, need))) {
      clear = true;
      return true;
    }
    if (clear_first && deep(s, slot)) return true;
    // A piece that is neither as a whole is often one or the other in parts: cheaper than the
    // cover below.
    if (part_passes(s, 0.0, 0.5, need, kSplitDepth) &&
        part_passes(s, 0.5, 1.0, need, kSplitDepth)) {
      return true;
    }
    // Near or inside B: drop the parts proven closer than `level` to A (all of the piece when
    // it lies inside B), then check the remaining gaps.
    std::vector<Interval> forbidden;
    if (far) forbidden.push_back({0.0, 1.0});
    const DPt p = s.p, q = s.q;
    q_.b->for_each_near(std::min(p.x, q.x) - need - 1, std::min(p.y, q.y) - need - 1,
                        std::max(p.x, q.x) + need + 1, std::max(p.y, q.y) + need + 1,
                        [&](std::size_t k) {
                          const Segment& g = q_.b->segments()[k];
                          Interval iv{};
                          if (stadium_interval(s, g.da(), g.db(), need + 1.0, iv))
                            forbidden.push_back(iv);
                        });
    if (gaps_are_clear(s, cover_intervals(s, forbidden), need)) return true;
    // A gap may have failed only for lying inside B away from its edges: try to cover it all.
    const std::vector<Interval> all{{0.0, 1.0}};
    return gaps_are_clear(s, cover_intervals(s, all), need);
  }

  // Intervals of the piece whose points are proven closer than level - error to some edge of
  // A (so the curve points they stand for are closer than level): proposed in double with a
  // smaller radius, then both endpoints are certified, and the stadium is convex. Stops once
  // `wanted` is covered. Returned merged and sorted.
  std::vector<Interval> cover_intervals(const Piece& s, const std::vector<Interval>& wanted) {
    const double l = q_.level;
    const double radius = l - s.error - 1.0;    // proposed with
    const double verify = sub_down(l, s.error); // certified against (strictly)
    std::vector<Interval> cover;
    const DPt p = s.p, q = s.q;
    bool done = false;
    q_.a->for_each_near(std::min(p.x, q.x) - l, std::min(p.y, q.y) - l, std::max(p.x, q.x) + l,
                        std::max(p.y, q.y) + l, [&](std::size_t k) {
                          if (done) return;
                          const Segment& g = q_.a->segments()[k];
                          Interval iv{};
                          if (!stadium_interval(s, g.da(), g.db(), radius, iv)) return;
                          if (!closer_than(on(s, iv.lo), g.a, g.b, verify) ||
                              !closer_than(on(s, iv.hi), g.a, g.b, verify)) {
                            return;
                          }
                          cover.push_back(iv);
                          if (cover.size() % 4 == 0) done = covers(merge(cover), wanted);
                        });
    return merge(cover);
  }

  static std::vector<Interval> merge(std::vector<Interval> v) {
    std::sort(v.begin(), v.end(), [](const Interval& x, const Interval& y) { return x.lo < y.lo; });
    std::vector<Interval> out;
    for (const Interval& iv : v) {
      if (!out.empty() && iv.lo <= out.back().hi) {
        out.back().hi = std::max(out.back().hi, iv.hi);
      } else {
        out.push_back(iv);
      }
    }
    return out;
  }

  static bool covers(const std::vector<Interval>& merged, const std::vector<Interval>& wanted) {
    for (const Interval& w : wanted) {
      bool inside = false;
      for (const Interval& m : merged) {
        if (m.lo <= w.lo && w.hi <= m.hi) inside = true;
      }
      if (!inside) return false;
    }
    return true;
  }

  // The parts of [0, 1] outside the merged cover must be far from B and outside it. Parameters
  // are exact doubles, so a gap [g0, g1] and its neighbouring cover intervals share endpoints.
  bool gaps_are_clear(const Piece& s, const std::vector<Interval>& cover, double need) {
    double start = 0.0;
    auto gap = [&](double g0, double g1) {
      if (g1 < g0) return true;
      return far_from_b(s, g0, g1, need) && outside_b(s, g0, g1, need);
    };
    for (const Interval& c : cover) {
      if (c.lo > start && !gap(start, c.lo)) return false;
      start = std::max(start, c.hi);
    }
    return start >= 1.0 || gap(start, 1.0);
  }

  const LevelSetQuery& q_;
  const CancelHook& cancel_;
  LevelSetMemo* memo_;
  unsigned pieces_ = 0;
  std::vector<Rep> in_, out_;
  // The edge of A that proved the last deep test: neighbouring pieces often lie deep behind
  // the same edge (some_edge_closer tries it first).
  std::size_t last_deep_ = static_cast<std::size_t>(-1);
  // Where the last checked piece ended when it was proven clear of B (continues_clear).
  std::optional<DPt> clear_end_;
};

} // namespace

bool level_set_avoids(const LevelSetQuery& query, const CancelHook& cancel) {
  Walker w(query, cancel);
  return w.run();
}

bool rings_are_simple(const SegmentIndex& index) {
  // The kernel's sweep: consecutive edges of a ring may share their common vertex (and do not
  // fold back), no other two edges may meet.
  const IRings& rings = index.rings();
  std::vector<std::span<const IPt>> spans(rings.begin(), rings.end());
  return !detail::find_ring_contact(spans).has_value();
}

bool rings_are_nested_consistently(const SegmentIndex& index) {
  const IRings& rings = index.rings();
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const int expected = twice_area(rings[r]) > 0 ? 0 : 1;
    if (index.winding_excluding(rings[r].front(), static_cast<std::uint32_t>(r)) != expected) {
      return false;
    }
  }
  return true;
}

} // namespace penshape::fast
