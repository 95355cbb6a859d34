// τ-simplification of a decided solution (see simplify.hpp for why the result is certified).
#include <algorithm>
#include <cmath>

#include "deconstruct/validate_input.hpp"
#include "engine/engines.hpp"
#include "engine/fast/fast_work.hpp"
#include "geometry/distance_kernel.hpp"
#include "geometry/douglas_peucker.hpp"
#include "geometry/segment_distance.hpp"
#include "penshape/core/convex_deconstruct.hpp"
#include "penshape/core/simplify.hpp"

namespace penshape {
namespace {

// Inputs with more vertices than this skip the work that grows too fast with their size.
constexpr std::size_t kLargeInput = 4096;

// Are all vertices strictly between i and j (cyclically) within τ of chord(i, j), exactly?
// Returns the index of the farthest offender, or n when all are within. Each vertex is cleared
// by a certified comparison (intervals, then exact rationals); the farthest offender is chosen
// among the rest by exact distances.
std::size_t farthest_offender(const Ring& ring, const std::vector<detail::IPoint>& iv,
                              std::size_t i, std::size_t j, const Rational& tau2,
                              const detail::IntervalNT& tau2i) {
  const std::size_t n = ring.size();
  std::size_t worst = n;
  Rational worst_d = tau2;
  for (std::size_t k = (i + 1) % n; k != j; k = (k + 1) % n) {
    if (detail::compare_squared_distance(ring[k], iv[k], ring[i], iv[i], ring[j], iv[j], tau2,
                                         tau2i) <= 0) {
      continue;
    }
    const Rational exact_d2 = detail::squared_distance_to_segment(ring[k], ring[i], ring[j]);
    if (exact_d2 > worst_d) {
      worst_d = exact_d2;
      worst = k;
    }
  }
  return worst;
}

Ring pick(const Ring& ring, const std::vector<std::size_t>& idx) {
  Ring out;
  out.reserve(idx.size());
  for (const auto i : idx) out.push_back(ring[i]);
  return out;
}

std::vector<const Ring*> all_rings(const PolygonSet& set) {
  std::vector<const Ring*> rings;
  for (const auto& p : set.polygons) {
    rings.push_back(&p.outer);
    for (const auto& h : p.holes) rings.push_back(&h);
  }
  return rings;
}

// The diameter pair of a ring's vertices (doubles; exactness is not needed to choose them).
std::pair<std::size_t, std::size_t> far_pair(const Ring& ring) {
  std::vector<PointD> d;
  for (const auto& p : ring) d.push_back(to_double(p));
  std::pair<std::size_t, std::size_t> best{0, 0};
  double best_d = -1;
  for (std::size_t i = 0; i < d.size(); ++i) {
    for (std::size_t j = i + 1; j < d.size(); ++j) {
      const double dd = std::hypot(d[i].x - d[j].x, d[i].y - d[j].y);
      if (dd > best_d) {
        best_d = dd;
        best = {i, j};
      }
    }
  }
  return best;
}

// A single ring within τ of the segment between its two farthest vertices collapses to that
// segment: the stadium around it is convex, so the vertices' check covers the region, and the
// region, connected between the endpoints, meets every perpendicular of the segment within it.
bool collapse_to_segment(PolygonSet& p, const PolygonSet& source, const Rational& tau2) {
  if (source.polygons.size() != 1 || !source.polygons[0].holes.empty()) return false;
  const Ring& ring = source.polygons[0].outer;
  if (ring.size() > kLargeInput) return false; // the quadratic diameter search would be slow
  const auto [a, b] = far_pair(ring);
  if (a == b) return false;
  for (const auto& v : ring) {
    if (detail::squared_distance_to_segment(v, ring[a], ring[b]) > tau2) return false;
  }
  p = PolygonSet{};
  p.polygons.push_back({{ring[a], ring[b]}, {}});
  return true;
}

} // namespace

std::vector<std::size_t> simplify_ring_indices(const Ring& ring, const Rational& tau) {
  const std::size_t n = ring.size();
  std::vector<std::size_t> keep;
  if (n <= 3) {
    for (std::size_t i = 0; i < n; ++i) keep.push_back(i);
    return keep;
  }
  std::vector<PointD> d;
  d.reserve(n);
  for (const auto& p : ring) d.push_back(to_double(p));
  const double tau_d = to_double(tau) * (1 - 1e-9); // doubles choose, rationals confirm
  // Douglas-Peucker on the closed ring, split at vertex 0 and the vertex farthest from it
  // (geometry/douglas_peucker.hpp): doubles choose, the confirmation below certifies.
  const std::size_t far = detail::farthest_from_first(
      n, [&](std::size_t k) { return std::hypot(d[k].x - d[0].x, d[k].y - d[0].y); });
  const std::vector<char> kept = detail::douglas_peucker_ring(
      n, far,
      [&](std::size_t k, std::size_t i, std::size_t j) {
        return detail::proposed_distance(d[k], d[i], d[j % n]);
      },
      [&](std::size_t, std::size_t, double worst) { return !(worst > tau_d); });
  for (std::size_t k = 0; k < n; ++k) {
    if (kept[k]) keep.push_back(k);
  }
  // Certified confirmation; split a chord at its farthest offender until all hold.
  const Rational tau2 = tau * tau;
  const detail::IntervalNT tau2i = detail::enclose(tau2);
  std::vector<detail::IPoint> iv;
  iv.reserve(n);
  for (const auto& p : ring) iv.push_back(detail::enclose(p));
  for (std::size_t t = 0; t < keep.size(); ++t) {
    const std::size_t from = keep[t];
    const std::size_t to = keep[(t + 1) % keep.size()];
    const std::size_t bad = farthest_offender(ring, iv, from, to, tau2, tau2i);
    if (bad != n) {
      keep.insert(keep.begin() + static_cast<std::ptrdiff_t>(t) + 1, bad);
      std::sort(keep.begin(), keep.end());
      t = static_cast<std::size_t>(-1); // recheck from the start: cheap, rare
    }
  }
  if (keep.size() < 3) { // a ring must keep an area; segments come from collapse_to_segment
    keep.clear();
    for (std::size_t k = 0; k < n; ++k) keep.push_back(k);
  }
  return keep;
}

std::size_t distinct_vertex_count(const PolygonSet& set) {
  std::size_t n = 0;
  for (const auto* ring : all_rings(set)) {
    if (sgn(twice_signed_area(*ring)) != 0) {
      n += ring->size();
      continue;
    }
    // A degenerate ring walks there and back: count each point once.
    std::vector<const ExactPoint*> seen;
    for (const auto& p : *ring) {
      const bool dup =
          std::any_of(seen.begin(), seen.end(), [&](const ExactPoint* s) { return *s == p; });
      if (!dup) seen.push_back(&p);
    }
    n += seen.size();
  }
  return n;
}

namespace {

// The decisions at ε' = ε - τ for τ = ε·tau_fraction, halving (options.attempts of them): each
// YES at ε' gives a certified P at ε by τ-simplification (the header's argument); the fewest
// vertices win, into `out`.
void tau_attempts(const PolygonSet& q, SimplifyResult& out, const CancelHook& cancel,
                  const DeconstructLimits& limits, const SimplifyOptions& options) {
  const DeconstructParams params = out.result.params;
  const std::size_t attempts = options.attempts;
  Rational tau = params.tolerance * options.tau_fraction;
  for (std::size_t attempt = 0; attempt < attempts; ++attempt, tau /= 2) {
    const Rational eps_prime = params.tolerance - tau;
    if (params.precision >= eps_prime) continue; // δ < ε' is the decider's precondition
    DeconstructParams tighter = params;
    tighter.tolerance = eps_prime;
    const DeconstructResult at_prime = deconstruct(q, tighter, cancel, limits);
    ++out.decider_calls;
    if (at_prime.answer != Answer::kYes) continue;

    const Rational tau2 = tau * tau;
    PolygonSet p;
    if (!(options.allow_degenerate && collapse_to_segment(p, at_prime.solution, tau2))) {
      p = at_prime.solution;
      for (auto& poly : p.polygons) {
        poly.outer = pick(poly.outer, simplify_ring_indices(poly.outer, tau));
        for (auto& h : poly.holes) h = pick(h, simplify_ring_indices(h, tau));
      }
      if (!detail::is_valid_region(p)) continue; // a chord crossed another ring: try a smaller τ
    }
    const std::size_t count = distinct_vertex_count(p);
    if (count >= out.solution_vertices) continue; // keep the best of all attempts
    out.result.solution = std::move(p);
    out.result.hausdorff_bound = params.tolerance;
    out.simplified = true;
    out.tau = tau;
    out.solution_vertices = count;
    if (count <= 2) break; // a segment: nothing simpler
  }
}

// simplify_solution, with the fast decision's work on this q when `work` is set.
SimplifyResult simplify_with(const PolygonSet& q, const DeconstructResult& raw,
                             detail::FastWork* work, const CancelHook& cancel,
                             const DeconstructLimits& limits, const SimplifyOptions& options) {
  if (raw.answer != Answer::kYes) throw InvalidInput("simplify_solution needs a YES solution");
  SimplifyResult out;
  out.result = raw;
  out.raw_vertices = distinct_vertex_count(raw.solution);
  out.solution_vertices = out.raw_vertices;
  const DeconstructParams& params = raw.params;
  if (params.radius <= params.tolerance) return out; // P = Q: nothing to gain by deciding again

  // Convex Q: the greedy P^s over eyelets has at most OPT + 1 vertices (Theorem 29).
  if (raw.engine == EngineKind::kFast && is_convex_region(q) && raw.solution.polygons.size() == 1 &&
      !raw.solution.polygons[0].outer.empty() && is_convex_region(raw.solution)) {
    const GreedyResult g =
        convex_greedy_solution(q, raw.solution, params.radius + params.tolerance, cancel);
    if (!g.fell_back && g.vertices < out.solution_vertices) {
      out.result.solution = g.solution;
      out.simplified = true;
      out.solution_vertices = g.vertices;
      return out;
    }
  }
  // The fast engine's own certificate can check any candidate directly, which uses all the
  // room Π leaves (not only the room between ε̂ and ε): try that first.
  if (raw.engine == EngineKind::kFast) {
    if (auto p = detail::simplify_fast_solution(q, params, raw.solution, cancel, work)) {
      const std::size_t count = distinct_vertex_count(*p);
      if (count < out.solution_vertices) {
        out.result.solution = std::move(*p);
        out.simplified = true;
        out.solution_vertices = count;
      }
    }
  }

  // Each τ attempt is a whole decision: on a large input (where collapse_to_segment does not
  // apply either), once the certificate's own simplification has succeeded, they are skipped
  // (issue 26: four decisions took 2.4 s of the CLI's 200,000-vertex call).
  if (out.simplified && q.vertex_count() > kLargeInput) return out;
  tau_attempts(q, out, cancel, limits, options);
  return out;
}

} // namespace

SimplifyResult simplify_solution(const PolygonSet& q, const DeconstructResult& raw,
                                 const CancelHook& cancel, const DeconstructLimits& limits,
                                 const SimplifyOptions& options) {
  return simplify_with(q, raw, nullptr, cancel, limits, options);
}

SimplifyResult deconstruct_simplified(const ValidatedRegion& q, const DeconstructParams& params,
                                      const CancelHook& cancel, const DeconstructLimits& limits,
                                      const SimplifyOptions& options) {
  std::unique_ptr<detail::FastWork> work;
  const DeconstructResult raw = detail::deconstruct_keeping(q, params, cancel, limits, work);
  if (raw.answer != Answer::kYes) {
    SimplifyResult out;
    out.result = raw;
    return out;
  }
  return simplify_with(q.region(), raw, work.get(), cancel, limits, options);
}

} // namespace penshape
