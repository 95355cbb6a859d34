#include "level_set_check.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace penshape::fast {
namespace {

// Error of a straight offset piece: the unit normal and its product with `level` in double.
constexpr double kStraightPieceError = 1.0 / 1024.0;
// Arc chords are refined down to this sagitta (grid units) before a piece counts as failed.
constexpr double kMinSagitta = 0.5;

struct Interval {
  double lo;
  double hi;
};

// A piece of the walked curve: y(t) = p + t (q - p), t in [0, 1]; every curve point it stands
// for lies within `error` of the piece and vice versa.
struct Piece {
  DPt p;
  DPt q;
  double error;
};

DPt at(const Piece& s, double t) {
  return {s.p.x + t * (s.q.x - s.p.x), s.p.y + t * (s.q.y - s.p.y)};
}

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
    Interval along, across;
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

class Walker {
 public:
  Walker(const LevelSetQuery& q, const CancelHook& cancel) : q_(q), cancel_(cancel) {}

  bool run() {
    const IRings& rings = q_.a->rings();
    for (const IRing& ring : rings) {
      const std::size_t n = ring.size();
      for (std::size_t i = 0; i < n; ++i) {
        const IPt prev = ring[(i + n - 1) % n];
        const IPt v = ring[i];
        const IPt next = ring[(i + 1) % n];
        if (!straight(v, next)) return false;
        if (orientation(prev, v, next) > 0 && !arc(prev, v, next)) return false;
        if ((++pieces_ & 255U) == 0 && cancel_ && cancel_()) throw Cancelled();
      }
    }
    return true;
  }

 private:
  static DPt right_normal(IPt a, IPt b) {
    const double dx = static_cast<double>(b.x - a.x), dy = static_cast<double>(b.y - a.y);
    const double len = std::hypot(dx, dy);
    return {dy / len, -dx / len};
  }

  bool straight(IPt a, IPt b) {
    const DPt n = right_normal(a, b);
    const double l = q_.level;
    return check({{static_cast<double>(a.x) + l * n.x, static_cast<double>(a.y) + l * n.y},
                  {static_cast<double>(b.x) + l * n.x, static_cast<double>(b.y) + l * n.y},
                  kStraightPieceError});
  }

  // The arc of radius `level` around a convex vertex v, from the outgoing normal of (prev, v)
  // to that of (v, next), counterclockwise, as chords with sagitta <= max_sagitta; a chord that
  // cannot be verified is split in two until its sagitta is below kMinSagitta.
  bool arc(IPt prev, IPt v, IPt next) {
    const DPt n0 = right_normal(prev, v);
    const DPt n1 = right_normal(v, next);
    const double a0 = std::atan2(n0.y, n0.x);
    double sweep = std::atan2(n1.y, n1.x) - a0;
    while (sweep < 0.0) sweep += 2.0 * M_PI;
    while (sweep >= 2.0 * M_PI) sweep -= 2.0 * M_PI;
    const double max_half = std::acos(std::max(0.0, 1.0 - q_.max_sagitta / q_.level));
    const int m = std::max(1, static_cast<int>(std::ceil(sweep / (2.0 * max_half))));
    const double step = sweep / m;
    for (int k = 0; k < m; ++k) {
      if (!arc_piece(to_d(v), a0 + step * k, a0 + step * (k + 1))) return false;
    }
    return true;
  }

  bool arc_piece(DPt c, double from, double to) {
    const double l = q_.level;
    const double sagitta = l * (1.0 - std::cos((to - from) / 2.0)) + kStraightPieceError;
    const Piece piece{{c.x + l * std::cos(from), c.y + l * std::sin(from)},
                      {c.x + l * std::cos(to), c.y + l * std::sin(to)},
                      sagitta};
    if (check(piece)) return true;
    if (sagitta < kMinSagitta) return false;
    const double mid = 0.5 * (from + to);
    return arc_piece(c, from, mid) && arc_piece(c, mid, to);
  }

  bool outside_b(DPt p) const { return q_.b->winding(round_point(p)) <= 0; }

  // Lower bound on the distance from the sub-piece [t0, t1] to B's edges, clipped at `need`.
  bool far_from_b(const Piece& s, double t0, double t1, double need) {
    const DPt p = at(s, t0), q = at(s, t1);
    bool ok = true;
    q_.b->for_each_near(
        std::min(p.x, q.x) - need, std::min(p.y, q.y) - need, std::max(p.x, q.x) + need,
        std::max(p.y, q.y) + need, [&](std::size_t k) {
          if (!ok) return;
          const Segment& g = q_.b->segments()[k];
          // Boxes farther apart than `need` cannot hold closer points.
          const double gx0 = static_cast<double>(std::min(g.a.x, g.b.x));
          const double gx1 = static_cast<double>(std::max(g.a.x, g.b.x));
          const double gy0 = static_cast<double>(std::min(g.a.y, g.b.y));
          const double gy1 = static_cast<double>(std::max(g.a.y, g.b.y));
          const double bx = std::max({gx0 - std::max(p.x, q.x), std::min(p.x, q.x) - gx1, 0.0});
          const double by = std::max({gy0 - std::max(p.y, q.y), std::min(p.y, q.y) - gy1, 0.0});
          if (bx * bx + by * by >= need * need) return;
          if (segment_segment_distance_lower(p, q, g.da(), g.db()) < need) ok = false;
        });
    return ok;
  }

  bool check(const Piece& s) {
    const DPt mid = at(s, 0.5);
    // Deep inside {d(·, A) < level}: every point of the piece is within half its length of the
    // midpoint, so a midpoint closer than level - half - error is proof enough (1-Lipschitz).
    const double half =
        0.5 * std::sqrt((s.q.x - s.p.x) * (s.q.x - s.p.x) + (s.q.y - s.p.y) * (s.q.y - s.p.y));
    const double deep = q_.level - half - s.error - kDistanceSlack;
    // Distance every represented curve point must keep from B's edges.
    const double need = q_.clearance + s.error + kDistanceSlack;
    const bool far = far_from_b(s, 0.0, 1.0, need);
    if (far && outside_b(mid)) return true;
    if (deep > 0.0 && q_.a->distance(mid, deep) < deep) return true;
    // Near or inside B: drop the parts provably closer than `level` to A (all of the piece when
    // it lies inside B), then check the remaining gaps.
    std::vector<Interval> forbidden;
    if (far) forbidden.push_back({0.0, 1.0});
    const DPt p = s.p, q = s.q;
    q_.b->for_each_near(std::min(p.x, q.x) - need - 1, std::min(p.y, q.y) - need - 1,
                        std::max(p.x, q.x) + need + 1, std::max(p.y, q.y) + need + 1,
                        [&](std::size_t k) {
                          const Segment& g = q_.b->segments()[k];
                          Interval iv;
                          if (stadium_interval(s, g.da(), g.db(), need + 1.0, iv))
                            forbidden.push_back(iv);
                        });
    if (gaps_are_clear(s, cover_intervals(s, forbidden), need)) return true;
    // A gap may have failed only for lying inside B away from its edges: try to cover it all.
    const std::vector<Interval> all{{0.0, 1.0}};
    return gaps_are_clear(s, cover_intervals(s, all), need);
  }

  // Verified intervals of the piece whose points are closer than `level` to some edge of A;
  // stops once `wanted` is covered. Returned merged and sorted.
  std::vector<Interval> cover_intervals(const Piece& s, const std::vector<Interval>& wanted) {
    const double l = q_.level;
    const double radius = l - s.error - 1.0; // computed with
    const double verify = l - s.error - 0.5; // checked against (convexity does the rest)
    std::vector<Interval> cover;
    const DPt p = s.p, q = s.q;
    bool done = false;
    q_.a->for_each_near(std::min(p.x, q.x) - l, std::min(p.y, q.y) - l, std::max(p.x, q.x) + l,
                        std::max(p.y, q.y) + l, [&](std::size_t k) {
                          if (done) return;
                          const Segment& g = q_.a->segments()[k];
                          Interval iv;
                          if (!stadium_interval(s, g.da(), g.db(), radius, iv)) return;
                          if (point_segment_distance(at(s, iv.lo), g.da(), g.db()) > verify ||
                              point_segment_distance(at(s, iv.hi), g.da(), g.db()) > verify) {
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

  // The parts of [0, 1] outside the merged cover must be far from B and outside it.
  bool gaps_are_clear(const Piece& s, const std::vector<Interval>& cover, double need) {
    double start = 0.0;
    auto gap = [&](double g0, double g1) {
      if (g1 < g0) return true;
      return far_from_b(s, g0, g1, need) && outside_b(at(s, 0.5 * (g0 + g1)));
    };
    for (const Interval& c : cover) {
      if (c.lo > start && !gap(start, c.lo)) return false;
      start = std::max(start, c.hi);
    }
    return start >= 1.0 || gap(start, 1.0);
  }

  const LevelSetQuery& q_;
  const CancelHook& cancel_;
  unsigned pieces_ = 0;
};

bool segments_intersect(IPt p1, IPt p2, IPt q1, IPt q2) {
  const int d1 = orientation(q1, q2, p1), d2 = orientation(q1, q2, p2);
  const int d3 = orientation(p1, p2, q1), d4 = orientation(p1, p2, q2);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  auto on = [](IPt a, IPt b, IPt c) {
    return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
           c.y <= std::max(a.y, b.y);
  };
  return (d1 == 0 && on(q1, q2, p1)) || (d2 == 0 && on(q1, q2, p2)) ||
         (d3 == 0 && on(p1, p2, q1)) || (d4 == 0 && on(p1, p2, q2));
}

} // namespace

bool level_set_avoids(const LevelSetQuery& query, const CancelHook& cancel) {
  Walker w(query, cancel);
  return w.run();
}

bool rings_are_simple(const SegmentIndex& index) {
  const auto& segs = index.segments();
  bool ok = true;
  for (std::size_t i = 0; i < segs.size() && ok; ++i) {
    const Segment& s = segs[i];
    index.for_each_near(
        static_cast<double>(std::min(s.a.x, s.b.x)), static_cast<double>(std::min(s.a.y, s.b.y)),
        static_cast<double>(std::max(s.a.x, s.b.x)), static_cast<double>(std::max(s.a.y, s.b.y)),
        [&](std::size_t j) {
          if (!ok || j <= i) return;
          const Segment& t = segs[j];
          const bool same_ring = s.ring == t.ring;
          const bool s_then_t = same_ring && (s.pos + 1) % s.ring_size == t.pos;
          const bool t_then_s = same_ring && (t.pos + 1) % t.ring_size == s.pos;
          if (s_then_t || t_then_s) {
            // Consecutive edges meet at their shared vertex only: no fold-back.
            const Segment& first = s_then_t ? s : t;
            const Segment& second = s_then_t ? t : s;
            if (orientation(first.a, first.b, second.b) == 0) {
              const std::int64_t dot = (first.b.x - first.a.x) * (second.b.x - second.a.x) +
                                       (first.b.y - first.a.y) * (second.b.y - second.a.y);
              if (dot < 0) ok = false;
            }
            return;
          }
          if (segments_intersect(s.a, s.b, t.a, t.b)) ok = false;
        });
  }
  return ok;
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
