// Translation and rotation (Section 3.3), linearized outer offset: sweeps over the one-parameter
// families of placements that make up the skeleton of the rotation diagrams (rotation.hpp, method
// 1).
#include "rotation_internal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "geometry/distance_kernel.hpp"
#include "point_set.hpp"
#include "prepared_annulus.hpp"
#include "translation_internal.hpp"

namespace penshape::annulus {
namespace detail {
namespace {

constexpr double kPi = std::numbers::pi;

inline PointD perp(PointD d) { return {d.y, -d.x}; } // R(-theta) d = cos * d + sin * perp(d)

// A boundary edge of the inner (hole) or outer linearized offset, template frame.
struct CurveEdge {
  PointD a, v, n;
  double H = 0.0;
};

// Distance from p to the segment [a, a + v]: the shared kernel's double path
// (geometry/distance_kernel.hpp); these are bounds the sweeps prune with, not certificates.
double point_segment_distance(PointD p, PointD a, PointD v) {
  return ::penshape::detail::proposed_distance(p, a, PointD{a.x + v.x, a.y + v.y});
}

struct RotationGeometry {
  std::vector<Edge> edges; // template edges (unit normals)
  double delta = 0.0;
  std::vector<CurveEdge> curve[2]; // 0: outer, 1: inner
  std::vector<PointD> corners[2];
  double diameter = 0.0;          // of the outer offset
  std::vector<double> dmin, dmax; // distance ranges between curve edges (flattened)
  std::size_t total = 0;

  bool has_hole = false;

  RotationGeometry(const TemplatePolygon& p, DeltaPair d) : delta(d.member) {
    const PreparedAnnulus an = prepare(p, OuterOffset::kLinearized, d);
    edges = an.edges;
    has_hole = an.has_hole;
    corners[0] = an.outer_poly;
    corners[1] = an.inner;
    for (int c = 0; c < 2; ++c) {
      const auto& poly = corners[c];
      for (std::size_t k = 0; k < poly.size(); ++k) {
        CurveEdge e;
        e.a = poly[k];
        e.v = poly[(k + 1) % poly.size()] - poly[k];
        const double len = norm(e.v);
        e.n = len > 0.0 ? PointD{e.v.y / len, -e.v.x / len} : PointD{0.0, 0.0};
        e.H = dot(e.n, e.a);
        if (len > 0.0) curve[c].push_back(e);
      }
    }
    for (const PointD& a : corners[0]) {
      for (const PointD& b : corners[0]) diameter = std::max(diameter, norm(a - b));
    }
    total = curve[0].size() + curve[1].size();
    dmin.assign(total * total, 0.0);
    dmax.assign(total * total, 0.0);
    for (std::size_t x = 0; x < total; ++x) {
      for (std::size_t y = 0; y < total; ++y) {
        const CurveEdge& e = at(x);
        const CurveEdge& f = at(y);
        const PointD e1 = e.a + e.v;
        const PointD f1 = f.a + f.v;
        double lo =
            std::min({point_segment_distance(e.a, f.a, f.v), point_segment_distance(e1, f.a, f.v),
                      point_segment_distance(f.a, e.a, e.v), point_segment_distance(f1, e.a, e.v)});
        // Crossing segments are at distance 0.
        const double o1 = cross(e.v, f.a - e.a);
        const double o2 = cross(e.v, f1 - e.a);
        const double o3 = cross(f.v, e.a - f.a);
        const double o4 = cross(f.v, e1 - f.a);
        if (o1 * o2 <= 0.0 && o3 * o4 <= 0.0) lo = 0.0;
        dmin[x * total + y] = lo;
        dmax[x * total + y] =
            std::max({norm(e.a - f.a), norm(e.a - f1), norm(e1 - f.a), norm(e1 - f1)});
      }
    }
  }
  [[nodiscard]] const CurveEdge& at(std::size_t x) const {
    return x < curve[0].size() ? curve[0][x] : curve[1][x - curve[0].size()];
  }
  [[nodiscard]] bool is_outer(std::size_t x) const { return x < curve[0].size(); }

  // W(theta) = k0 + kc cos + ks sin over an angle range: its value at the middle and the half
  // width of the range.
  struct Curve {
    PointD k0, kc, ks, wm;
    double half = 0.0;
  };

  // The angles of `V` where W lies in the template offset by s (n . W <= h + s for every edge).
  // Per constraint: n . W moves at most (|n.kc| + |n.ks|) * half over V; constraints that hold
  // (or fail) on all of V need no trigonometry.
  [[nodiscard]] IntervalSet within(const Curve& w, double s, IntervalSet V) const {
    for (const Edge& e : edges) {
      const double A = dot(e.n, w.kc);
      const double B = dot(e.n, w.ks);
      const double C = e.h + s - dot(e.n, w.k0);
      const double v = dot(e.n, w.wm) - e.h - s; // <= 0 inside
      const double r = (std::abs(A) + std::abs(B)) * w.half;
      if (v + r < 0.0) continue;
      if (v - r > 0.0) return {};
      IntervalSet next;
      for (const Interval& iv : V) trig_leq(A, B, C, iv.lo, iv.hi, next);
      V.swap(next);
      if (V.empty()) return V;
    }
    return V;
  }

  // Angles in `V` where W(theta) = k0 + kc cos + ks sin lies in the annulus.
  [[nodiscard]] IntervalSet member(PointD k0, PointD kc, PointD ks, const IntervalSet& V) const {
    if (V.empty()) return {};
    const double lo = V.front().lo;
    const double hi = V.back().hi;
    const double mid = 0.5 * (lo + hi);
    const double reach = (norm(kc) + norm(ks)) * 0.5 * (hi - lo);
    const PointD wm = k0 + (kc * std::cos(mid) + ks * std::sin(mid));
    double f = -std::numeric_limits<double>::infinity();
    for (const Edge& e : edges) f = std::max(f, dot(e.n, wm) - e.h);
    // f is 1-Lipschitz and W moves at most `reach` over V.
    if (f > delta + reach) return {};
    if (f < -delta - reach && has_hole) return {};
    if (f <= delta - reach && (f >= -delta + reach || !has_hole)) return V;
    const double half = 0.5 * (hi - lo);
    const Curve w{k0, kc, ks, wm, half};
    IntervalSet out = within(w, delta, V);
    if (out.empty() || !has_hole) return out;
    IntervalSet hole = within(w, -delta, V);
    if (hole.empty()) return out; // the hole misses all of V
    // Hole ends clamped by V are not boundaries of the open hole: push them just past.
    for (Interval& h : hole) {
      for (const Interval& v : V) {
        if (h.lo == v.lo) h.lo = std::nextafter(h.lo, -INFINITY);
        if (h.hi == v.hi) h.hi = std::nextafter(h.hi, INFINITY);
      }
    }
    return subtract_interior(out, hole);
  }
};

void restrict_trig(IntervalSet& V, double A, double B, double C) {
  IntervalSet next;
  for (const Interval& iv : V) trig_leq(A, B, C, iv.lo, iv.hi, next);
  V.swap(next);
}

// A family: the template point of anchor i is z(theta) = Z0 + Zc cos + Zs sin.
struct Family {
  std::size_t i;
  std::size_t j; // second contact, or SIZE_MAX
  PointD Z0, Zc, Zs;
  IntervalSet V;
};

Placement placement_at(const Family& f, PointD qi, double theta) {
  Placement pl;
  pl.tan_half_theta = std::tan(0.5 * theta);
  const double u = pl.tan_half_theta;
  const double c = (1.0 - u * u) / (1.0 + u * u);
  const double s = 2.0 * u / (1.0 + u * u);
  pl.theta = 2.0 * std::atan(u);
  const PointD z = f.Z0 + (f.Zc * c + f.Zs * s);
  pl.tx = qi.x - (c * z.x - s * z.y);
  pl.ty = qi.y - (s * z.x + c * z.y);
  return pl;
}

struct Search {
  Search(const TemplatePolygon& p_, const std::vector<PointD>& original_, const WeightedPoints& wp_,
         const RotationGeometry& g_, bool decide_, bool verify_, const std::vector<bool>* hull_,
         std::vector<std::size_t> order_, double tol_, double delta_check_)
      : p(p_),
        original(original_),
        wp(wp_),
        g(g_),
        decide(decide_),
        verify(verify_),
        hull(hull_),
        order(std::move(order_)),
        tol(tol_),
        delta_check(delta_check_) {}

  const TemplatePolygon& p;
  const std::vector<PointD>& original;
  const WeightedPoints& wp;
  const RotationGeometry& g;
  bool decide;                   // decision mode: every point must be contained
  bool verify;                   // decision mode: check witnesses exactly (else any survivor)
  const std::vector<bool>* hull; // decision mode: outer contacts only on hull points
  std::vector<std::size_t> order;
  double tol;
  // Results.
  std::size_t best = 0;
  Placement best_placement;
  bool found = false;
  bool undecided = false;
  double delta_check = 0.0; // decision: delta for the exact check
  struct Event {
    double pos;
    long w;
  };
  std::vector<Event> events;
  // Which family gave the best count (i, j, edge or corner indices), and a filter that makes
  // enumerate() visit only that family (used to re-find the witness in the narrowed annulus).
  std::array<std::size_t, 4> best_key{};
  std::optional<std::array<std::size_t, 4>> only;
  std::array<std::size_t, 4> key{};

  // Returns true to stop the search (decision found).
  bool run(const Family& f) { return decide ? run_decision(f) : run_count(f); }

  // Decision mode: narrows the family's angles by every point in turn (the last one to empty
  // them moves to the front of `order`); a survivor is the witness, checked exactly if `verify`.
  bool run_decision(const Family& f) {
    const auto& pts = wp.points;
    const PointD qi = pts[f.i];
    IntervalSet S = f.V;
    for (std::size_t t = 0; t < order.size(); ++t) {
      const std::size_t k = order[t];
      if (k == f.i || k == f.j) continue;
      const PointD d = pts[k] - qi;
      if (norm(d) > g.diameter + tol) {
        S.clear();
      } else {
        S = g.member(f.Z0, f.Zc + d, f.Zs + perp(d), S);
      }
      if (S.empty()) {
        std::swap(order[t], order[0]);
        return false;
      }
    }
    std::size_t bi = 0;
    for (std::size_t x = 1; x < S.size(); ++x) {
      if (S[x].hi - S[x].lo > S[bi].hi - S[bi].lo) bi = x;
    }
    const Placement pl = placement_at(f, qi, 0.5 * (S[bi].lo + S[bi].hi));
    if (!verify) {
      found = true;
      return true;
    }
    if (covered_exactly(p, OuterOffset::kLinearized, delta_check, pl, original).size() ==
        original.size()) {
      best_placement = pl;
      found = true;
      return true;
    }
    undecided = true;
    return false;
  }

  // Counting mode: sweeps the family's angles, each point's weight entering and leaving with
  // its membership intervals, and keeps the best count seen.
  bool run_count(const Family& f) {
    const auto& pts = wp.points;
    const PointD qi = pts[f.i];
    events.clear();
    const long base = static_cast<long>(wp.weight[f.i]) +
                      (f.j == SIZE_MAX ? 0L : static_cast<long>(wp.weight[f.j]));
    for (std::size_t k = 0; k < pts.size(); ++k) {
      if (k == f.i || k == f.j) continue;
      const PointD d = pts[k] - qi;
      if (norm(d) > g.diameter + tol) continue;
      const long w = static_cast<long>(wp.weight[k]);
      for (const Interval& iv : g.member(f.Z0, f.Zc + d, f.Zs + perp(d), f.V)) {
        events.push_back({iv.lo, w});
        events.push_back({iv.hi, -w});
      }
    }
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
      return a.pos < b.pos || (a.pos == b.pos && a.w > b.w);
    });
    long cur = base;
    if (static_cast<std::size_t>(cur) > best) {
      record_best(cur, placement_at(f, qi, 0.5 * (f.V.front().lo + f.V.front().hi)));
    }
    for (std::size_t e = 0; e < events.size(); ++e) {
      cur += events[e].w;
      if (static_cast<std::size_t>(cur) > best) {
        const double next = e + 1 < events.size() ? events[e + 1].pos : events[e].pos;
        record_best(cur, placement_at(f, qi, 0.5 * (events[e].pos + next)));
      }
    }
    return false;
  }

  void record_best(long count, const Placement& placement) {
    best = static_cast<std::size_t>(count);
    best_placement = placement;
    best_key = key;
    found = true;
  }

  // Visits every family of the skeleton (or only the `only` one) until run() stops the search.
  void enumerate() {
    if (enumerate_corners()) return;
    enumerate_edge_pairs();
  }

  // A decision's outer contacts are hull points only (an inner one may be any point).
  [[nodiscard]] bool contact_allowed(bool outer, std::size_t point) const {
    return !(decide && outer && !(*hull)[point]);
  }

  // One point at a corner of an offset boundary; true when the search stopped.
  bool enumerate_corners() {
    const IntervalSet full{{-kPi, kPi}};
    for (std::size_t i = 0; i < wp.points.size(); ++i) {
      for (std::size_t c = 0; c < 2; ++c) {
        if (!contact_allowed(c == 0, i)) continue;
        for (std::size_t z = 0; z < g.corners[c].size(); ++z) {
          key = {i, SIZE_MAX, c, z};
          if (only && *only != key) continue;
          if (run(Family{i, SIZE_MAX, g.corners[c][z], {0, 0}, {0, 0}, full})) return true;
        }
      }
    }
    return false;
  }

  // Two points on two boundary edges; true when the search stopped.
  bool enumerate_edge_pairs() {
    const auto& pts = wp.points;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      for (std::size_t j = i + 1; j < pts.size(); ++j) {
        if (norm(pts[j] - pts[i]) > g.diameter + tol) continue;
        if (enumerate_edge_pairs_of(i, j)) return true;
      }
    }
    return false;
  }

  // Points i and j on edges x and y of the offset boundaries, for every (x, y) their distance
  // allows; true when the search stopped.
  bool enumerate_edge_pairs_of(std::size_t i, std::size_t j) {
    const double rho = norm(wp.points[j] - wp.points[i]);
    for (std::size_t x = 0; x < g.total; ++x) {
      if (!contact_allowed(g.is_outer(x), i)) continue;
      for (std::size_t y = 0; y < g.total; ++y) {
        if (!contact_allowed(g.is_outer(y), j)) continue;
        if (rho < g.dmin[x * g.total + y] - tol || rho > g.dmax[x * g.total + y] + tol) continue;
        const std::optional<Family> f = edge_pair_family(i, j, x, y);
        if (!f) continue;
        key = {i, j, x, y};
        if (only && *only != key) continue;
        if (run(*f)) return true;
      }
    }
    return false;
  }

  // The family where point i slides on edge x and point j on edge y, with the angles at which
  // both stay on their edges; none when there are no such angles or the edges are parallel.
  [[nodiscard]] std::optional<Family> edge_pair_family(std::size_t i, std::size_t j, std::size_t x,
                                                       std::size_t y) const {
    const PointD d = wp.points[j] - wp.points[i];
    const PointD dp = perp(d);
    const CurveEdge& ea = g.at(x);
    const CurveEdge& eb = g.at(y);
    const double nbea = dot(eb.n, ea.v);
    if (std::abs(nbea) <= 1e-12 * norm(ea.v)) return std::nullopt; // parallel contact edges
    const double a0 = (eb.H - dot(eb.n, ea.a)) / nbea;
    const double ac = -dot(eb.n, d) / nbea;
    const double as = -dot(eb.n, dp) / nbea;
    IntervalSet V{{-kPi, kPi}};
    restrict_trig(V, -ac, -as, a0);     // sigma >= 0
    restrict_trig(V, ac, as, 1.0 - a0); // sigma <= 1
    if (V.empty()) return std::nullopt;
    const PointD Z0 = ea.a + ea.v * a0;
    const PointD Zc = ea.v * ac;
    const PointD Zs = ea.v * as;
    const double L2 = dot(eb.v, eb.v);
    const double t0 = dot(Z0 - eb.a, eb.v) / L2;
    const double tc = dot(Zc + d, eb.v) / L2;
    const double ts = dot(Zs + dp, eb.v) / L2;
    restrict_trig(V, -tc, -ts, t0);     // j's position on edge b >= 0
    restrict_trig(V, tc, ts, 1.0 - t0); // <= 1
    if (V.empty()) return std::nullopt;
    return Family{i, j, Z0, Zc, Zs, std::move(V)};
  }
};

DecisionResult decide_rotation_core(const TemplatePolygon& p, double delta,
                                    const std::vector<PointD>& points, const WeightedPoints& wp,
                                    const std::vector<bool>& hull, std::vector<std::size_t>& order,
                                    const Placement* hint) {
  DecisionResult r;
  r.margin = annulus_margin(p, delta, points);
  for (const Placement& guess : {centred_placement(p, points), hint ? *hint : Placement{}}) {
    if (width_at(p, OuterOffset::kLinearized, guess, points) <= delta &&
        covered_exactly(p, OuterOffset::kLinearized, delta, guess, points).size() ==
            points.size()) {
      r.answer = Answer::kYes;
      r.placement = guess;
      return r;
    }
  }
  // NO with the widened annulus, witnesses from the narrowed one (see translation.cpp).
  {
    const RotationGeometry wide(p, widened(delta, r.margin));
    Search s(p, points, wp, wide, true, false, &hull, std::move(order), 10.0 * r.margin, delta);
    s.enumerate();
    order = std::move(s.order);
    if (!s.found) {
      r.answer = Answer::kNo;
      return r;
    }
  }
  const RotationGeometry narrow(p, narrowed(delta, r.margin));
  Search s(p, points, wp, narrow, true, true, &hull, std::move(order), 10.0 * r.margin, delta);
  s.enumerate();
  order = std::move(s.order);
  r.answer = s.found ? Answer::kYes : Answer::kUndecided;
  if (s.found) r.placement = s.best_placement;
  return r;
}

// The subset of a Clarkson iteration: points taken once each, in the order taken.
struct Subset {
  explicit Subset(const std::vector<PointD>& all) : points(all), taken(all.size(), 0) {}
  void take(std::size_t i) {
    if (!taken[i]) {
      taken[i] = 1;
      chosen.push_back(points[i]);
    }
  }
  const std::vector<PointD>& points;
  std::vector<char> taken;
  std::vector<PointD> chosen;
};

// The first subset: the extreme point in each of 8 directions, and 8 points spread over the input.
void seed(Subset& subset) {
  const std::vector<PointD>& points = subset.points;
  const std::size_t n = points.size();
  for (int k = 0; k < 8; ++k) {
    const double a = kPi * k / 4.0;
    const PointD dir{std::cos(a), std::sin(a)};
    std::size_t best = 0;
    for (std::size_t i = 1; i < n; ++i) {
      if (dot(points[i], dir) > dot(points[best], dir)) best = i;
    }
    subset.take(best);
    subset.take(static_cast<std::size_t>(k) * n / 8);
  }
}

// Up to 8 of the points `placement` misses (`covered` lists the others, ascending), the worst
// first.
std::vector<std::size_t> worst_missed(const TemplatePolygon& p, const std::vector<PointD>& points,
                                      const Placement& placement,
                                      const std::vector<std::size_t>& covered) {
  std::vector<std::pair<double, std::size_t>> missed;
  std::size_t c = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (c < covered.size() && covered[c] == i) {
      ++c;
      continue;
    }
    missed.push_back({-width_at(p, OuterOffset::kLinearized, placement, {points[i]}), i});
  }
  const std::size_t take_n = std::min<std::size_t>(8, missed.size());
  std::partial_sort(missed.begin(), missed.begin() + static_cast<std::ptrdiff_t>(take_n),
                    missed.end());
  std::vector<std::size_t> worst(take_n);
  for (std::size_t k = 0; k < take_n; ++k) worst[k] = missed[k].second;
  return worst;
}

// The decision on the subset's points alone.
DecisionResult decide_subset(const TemplatePolygon& p, double delta,
                             const std::vector<PointD>& subset,
                             const std::optional<Placement>& hint) {
  const WeightedPoints wp = merge_duplicates(subset);
  const std::vector<bool> hull = hull_boundary(wp.points);
  std::vector<std::size_t> order(wp.points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  return decide_rotation_core(p, delta, subset, wp, hull, order, hint ? &*hint : nullptr);
}

// Clarkson-style iteration: decide on a small subset first. A robust NO for the subset is a NO
// for all points; a subset witness that misses points brings the worst missed points in.
DecisionResult decide_rotation_iterative(const TemplatePolygon& p, double delta,
                                         const std::vector<PointD>& points, const Placement* hint) {
  const std::size_t n = points.size();
  Subset subset(points);
  seed(subset);
  std::optional<Placement> last;
  if (hint) last = *hint;
  for (;;) {
    DecisionResult r = decide_subset(p, delta, subset.chosen, last);
    if (r.answer == Answer::kNo) return r;
    if (r.answer == Answer::kUndecided) {
      if (subset.chosen.size() == n) return r;
      for (std::size_t i = 0; i < n; ++i) subset.take(i); // undecided on the subset: use all
      continue;
    }
    const auto covered = covered_exactly(p, OuterOffset::kLinearized, delta, r.placement, points);
    if (covered.size() == n) return r;
    last = r.placement;
    for (const std::size_t i : worst_missed(p, points, r.placement, covered)) subset.take(i);
  }
}

} // namespace

MaxCoverResult max_cover_rotation_diagram(const TemplatePolygon& p, double delta,
                                          const std::vector<PointD>& points) {
  const WeightedPoints wp = merge_duplicates(points);
  const double margin = annulus_margin(p, delta, points);
  MaxCoverResult res;
  std::array<std::size_t, 4> best_key{};
  {
    const RotationGeometry wide(p, widened(delta, margin));
    Search s(p, points, wp, wide, false, false, nullptr, {}, 10.0 * margin, delta);
    s.enumerate();
    res.upper_bound = s.best;
    best_key = s.best_key;
  }
  // The witness: first only the family that gave the upper bound, in the narrowed annulus.
  const RotationGeometry narrow(p, narrowed(delta, margin));
  Search s(p, points, wp, narrow, false, false, nullptr, {}, 10.0 * margin, delta);
  s.only = best_key;
  s.enumerate();
  res.placement = s.best_placement;
  if (s.best < res.upper_bound) {
    Search full(p, points, wp, narrow, false, false, nullptr, {}, 10.0 * margin, delta);
    full.enumerate();
    res.placement = full.best_placement;
  }
  res.covered = covered_exactly(p, OuterOffset::kLinearized, delta, res.placement, points);
  return res;
}

DecisionResult decide_rotation_diagram(const TemplatePolygon& p, double delta,
                                       const std::vector<PointD>& points) {
  return decide_rotation_iterative(p, delta, points, nullptr);
}

MinWidthResult min_width_rotation_diagram(const TemplatePolygon& p,
                                          const std::vector<PointD>& points,
                                          const MinWidthOptions& options) {
  return bisect_min_width(p, OuterOffset::kLinearized, points, options,
                          [&](double width, Placement& hint) {
                            return decide_rotation_iterative(p, width, points, &hint);
                          });
}

} // namespace detail
} // namespace penshape::annulus
