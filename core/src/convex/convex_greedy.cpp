// The greedy P^s over eyelets (Section 5). Floating point finds the horizons; exact rational
// arithmetic certifies the result (or falls back to Π̂).
#include <algorithm>
#include <cmath>

#include "convex_inset.hpp"
#include "geometry/distance_kernel.hpp"
#include "penshape/core/convex_deconstruct.hpp"

namespace penshape {
namespace {

struct Boundary {
  std::vector<PointD> w; // Π̂'s vertices, counterclockwise
  [[nodiscard]] std::size_t size() const { return w.size(); }
  // Boundary parameter s ∈ [0, m): edge floor(s), fraction s - floor(s).
  [[nodiscard]] PointD at(double s) const {
    const auto m = static_cast<double>(w.size());
    s = std::fmod(std::fmod(s, m) + m, m);
    const auto e = static_cast<std::size_t>(s);
    const double t = s - static_cast<double>(e);
    const PointD a = w[e % w.size()];
    const PointD b = w[(e + 1) % w.size()];
    return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
  }
};

double dist(PointD a, PointD b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Parameter on edge e of the point nearest to q.
double nearest_on_edge(const Boundary& bd, std::size_t e, PointD q) {
  const PointD a = bd.w[e];
  const PointD b = bd.w[(e + 1) % bd.size()];
  return static_cast<double>(e) + detail::proposed_foot_parameter(q, a, b);
}

// The spot of eyelet i: where the boundary arc within `reach` of q, around q's nearest boundary
// point, begins (counterclockwise). `hint` is the previous vertex's nearest edge.
double spot_of(const Boundary& bd, PointD q, double reach, std::size_t& hint) {
  const std::size_t m = bd.size();
  auto edge_dist = [&](std::size_t e) { return dist(q, bd.at(nearest_on_edge(bd, e % m, q))); };
  // Local descent from the hint; a full scan when the hint is far off.
  std::size_t best = hint % m;
  double best_d = edge_dist(best);
  for (std::size_t k = 1; k < m; ++k) {
    const double d = edge_dist(best + 1);
    if (d > best_d) break;
    best = (best + 1) % m;
    best_d = d;
  }
  if (best_d > reach) {
    for (std::size_t e = 0; e < m; ++e) {
      const double d = edge_dist(e);
      if (d < best_d) {
        best = e;
        best_d = d;
      }
    }
  }
  hint = best;
  double s = nearest_on_edge(bd, best, q);
  // Walk backwards (unwrapped parameters) to where the distance reaches `reach`: whole edges
  // while their start is still within reach, then bisection inside the crossing edge.
  for (std::size_t k = 0; k < m; ++k) {
    const double start = std::ceil(s) - 1.0; // the vertex at or before s, strictly before
    if (dist(q, bd.at(start)) <= reach) {
      s = start;
      continue;
    }
    double lo = start; // outside
    double hi = s;     // inside
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (dist(q, bd.at(mid)) <= reach ? hi : lo) = mid;
    }
    s = hi;
    break;
  }
  const auto md = static_cast<double>(m);
  return std::fmod(std::fmod(s, md) + md, md);
}

struct Eyelet {
  double spot; // boundary parameter
  PointD q;    // the vertex of Q
};

// Spots unwrapped into (u, u + m], sorted: the eyelets a chord from u can pass, in order.
struct SpotsAfter {
  std::vector<double> spot;
  std::vector<PointD> q;
};

SpotsAfter spots_after(const std::vector<Eyelet>& eyelets, double u, double m) {
  std::vector<std::pair<double, PointD>> v;
  v.reserve(eyelets.size());
  for (const auto& ey : eyelets) {
    const double k = std::floor((u - ey.spot) / m) + 1.0; // smallest k with spot + k·m > u
    v.emplace_back(ey.spot + k * m, ey.q);
  }
  std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  SpotsAfter out;
  for (const auto& [s, q] : v) {
    out.spot.push_back(s);
    out.q.push_back(q);
  }
  return out;
}

// Is the chord from boundary parameter u to s good: does it meet the disk of every eyelet whose
// spot lies strictly between them (Definition 26)?
bool good_chord(const Boundary& bd, const SpotsAfter& spots, double u, double s, double reach) {
  const PointD a = bd.at(u);
  const PointD b = bd.at(s);
  for (std::size_t i = 0; i < spots.spot.size() && spots.spot[i] < s; ++i) {
    // Doubles choose the horizons; the returned polygon is checked exactly.
    if (detail::proposed_distance(spots.q[i], a, b) > reach) return false;
  }
  return true;
}

// The horizon of u (Section 5): the farthest boundary parameter in (u, limit] whose chord from u
// is good. Goodness shrinks monotonically as the chord's end moves on (Lemma 28's argument), so
// bisection finds it.
double horizon(const Boundary& bd, const std::vector<Eyelet>& eyelets, double u, double limit,
               double reach) {
  const SpotsAfter spots = spots_after(eyelets, u, static_cast<double>(bd.size()));
  if (good_chord(bd, spots, u, limit, reach)) return limit;
  double lo = u;
  double hi = limit;
  for (int it = 0; it < 64; ++it) {
    const double mid = 0.5 * (lo + hi);
    (good_chord(bd, spots, u, mid, reach) ? lo : hi) = mid;
  }
  return lo;
}

// The exact boundary point at parameter s of the rational ring.
ExactPoint exact_at(const Ring& ring, double s) {
  const auto m = static_cast<double>(ring.size());
  s = std::fmod(std::fmod(s, m) + m, m);
  const auto e = static_cast<std::size_t>(s) % ring.size();
  const Rational t = exact(s - std::floor(s));
  const ExactPoint& a = ring[e];
  const ExactPoint& b = ring[(e + 1) % ring.size()];
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

bool every_vertex_reaches(const Ring& q, const Ring& p, const Rational& reach2,
                          const CancelHook& cancel) {
  for (std::size_t i = 0; i < q.size(); ++i) {
    if ((i & 63U) == 0 && cancel && cancel()) throw Cancelled();
    bool ok = false;
    if (p.size() == 1) {
      const Rational dx = q[i].x - p[0].x;
      const Rational dy = q[i].y - p[0].y;
      ok = dx * dx + dy * dy <= reach2;
    }
    for (std::size_t e = 0; e < p.size() && !ok && p.size() > 1; ++e) {
      ok = detail::squared_distance_to_segment(q[i], p[e], p[(e + 1) % p.size()]) <= reach2;
    }
    if (!ok) return false;
  }
  return true;
}

} // namespace

GreedyResult convex_greedy_solution(const PolygonSet& q, const PolygonSet& pi_hat,
                                    const Rational& reach, const CancelHook& cancel) {
  GreedyResult out;
  out.solution = pi_hat;
  out.fell_back = true;
  if (pi_hat.polygons.size() != 1 || q.polygons.size() != 1) return out;
  const Ring& ring = pi_hat.polygons[0].outer;
  const Ring& qring = q.polygons[0].outer;
  out.vertices = ring.size();
  if (ring.size() < 3) return out;

  Boundary bd;
  for (const auto& p : ring) bd.w.push_back(to_double(p));
  // Doubles choose, rationals certify: a relative margin keeps borderline chords out.
  const double r = to_double(reach) * (1 - 1e-9);
  std::vector<Eyelet> eyelets;
  eyelets.reserve(qring.size());
  std::size_t hint = 0;
  for (const auto& p : qring) {
    const PointD qd = to_double(p);
    eyelets.push_back({spot_of(bd, qd, r, hint), qd});
  }
  const auto m = static_cast<double>(bd.size());
  // P^s from the first eyelet's spot, then from each of its vertices: a start that is a vertex
  // of an optimal solution gives OPT (Theorem 29), so the best of these is often optimal.
  const auto greedy_from = [&](double s0) {
    std::vector<double> params{s0};
    const double limit = s0 + m;
    for (std::size_t guard = 0; guard < qring.size() + 2; ++guard) {
      if (cancel && cancel()) throw Cancelled();
      const double h = horizon(bd, eyelets, params.back(), limit, r);
      if (h >= limit) break; // the chord back to s0 is good
      // Step back a hair so rounding cannot carry the vertex past the true horizon.
      params.push_back(std::max(params.back() + 1e-9, h - 1e-9 * m));
    }
    return params;
  };
  std::vector<double> params = greedy_from(eyelets.front().spot);
  const std::vector<double> starts = params;
  for (std::size_t i = 1; i < starts.size(); ++i) {
    std::vector<double> alt = greedy_from(std::fmod(starts[i], m));
    if (alt.size() < params.size()) params = std::move(alt);
  }
  Ring p;
  for (const double s : params) p.push_back(exact_at(ring, s));
  // Remove coincident vertices (a point or segment solution may repeat one).
  p.erase(std::unique(p.begin(), p.end()), p.end());
  while (p.size() > 1 && p.front() == p.back()) p.pop_back();
  if (!every_vertex_reaches(qring, p, reach * reach, cancel)) return out;
  out.solution = PolygonSet{};
  out.solution.polygons.push_back({std::move(p), {}});
  out.vertices = out.solution.polygons[0].outer.size();
  out.fell_back = false;
  return out;
}

} // namespace penshape
