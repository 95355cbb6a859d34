// CONVEXDECIDE (Algorithm 6). The common cases are answered from double-precision candidates
// certified exactly: YES by an inner polygon proven inside Π (no square roots needed) that every
// vertex disk of Q reaches; NO by a vertex q of Q and one or two of Π's half-planes, widened
// with rational bounds, whose intersection the disk around q misses (Helly: then Π misses it
// too). Whatever they cannot certify goes to the exact rational path, which brackets |n| by
// rationals and intersects exactly.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "convex_exact_inset.hpp"
#include "convex_inset.hpp"
#include "geometry/distance_kernel.hpp"
#include "geometry/exact_predicates.hpp"
#include "penshape/core/convex_deconstruct.hpp"
#include "penshape/core/simplify.hpp"

namespace penshape {
namespace {

// The exact path brackets |n| to a relative 2^-kSqrtBits, far below any δ a caller can ask for.
constexpr unsigned kSqrtBits = 64;

// For each vertex q_i of Q (counterclockwise), is some edge of the convex ring `pi` within
// distance R? Walks the edges from where the previous vertex found one (Lemma 23's linear scan).
// Each comparison is certified (geometry/distance_kernel.hpp: intervals, then exact rationals).
// Returns the index of the first vertex that fails, or q.size().
std::size_t first_vertex_missing(const Ring& q, const Ring& pi, const Rational& r2,
                                 const CancelHook& cancel) {
  const std::size_t m = pi.size();
  std::vector<detail::IPoint> qi, pii;
  qi.reserve(q.size());
  pii.reserve(m);
  for (const auto& v : q) qi.push_back(detail::enclose(v));
  for (const auto& v : pi) pii.push_back(detail::enclose(v));
  const detail::IntervalNT r2i = detail::enclose(r2);
  std::size_t edge = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    if ((i & 63U) == 0 && cancel && cancel()) throw Cancelled();
    bool found = false;
    for (std::size_t k = 0; k < m && !found; ++k) {
      const std::size_t e = (edge + k) % m;
      const std::size_t f = (e + 1) % m;
      found =
          detail::compare_squared_distance(q[i], qi[i], pi[e], pii[e], pi[f], pii[f], r2, r2i) <= 0;
      if (found) edge = e;
    }
    if (!found) return i;
  }
  return q.size();
}

// a·x + b·y <= c for edge j of the exact counterclockwise ring, shifted inward by at most
// `shift`·|n| (a superset of the exact shifted half-plane).
detail::HalfPlane widened_half_plane(const Ring& ring, std::size_t j, const Rational& shift) {
  std::vector<ExactPoint> edge{ring[j], ring[(j + 1) % ring.size()]};
  const auto bound = sgn(shift) >= 0 ? detail::ShiftBound::kLower : detail::ShiftBound::kUpper;
  // shifted_edge_half_planes works on a ring; a two-point "ring" yields this edge first.
  return detail::shifted_edge_half_planes(edge, shift, bound, kSqrtBits).front();
}

bool inside(const detail::HalfPlane& h, const ExactPoint& p) {
  return h.a * p.x + h.b * p.y <= h.c;
}

ExactPoint project(const detail::HalfPlane& h, const ExactPoint& p) {
  const Rational over = (h.a * p.x + h.b * p.y - h.c) / (h.a * h.a + h.b * h.b);
  return {p.x - over * h.a, p.y - over * h.b};
}

Rational squared_length(const ExactPoint& a, const ExactPoint& b) {
  const Rational dx = a.x - b.x;
  const Rational dy = a.y - b.y;
  return dx * dx + dy * dy;
}

// Exact: does the disk of squared radius r2 around q miss the intersection of the half-planes?
// (One or two of them.) The nearest point of a wedge is a projection onto one of its lines or
// its apex.
bool disk_misses(const ExactPoint& q, const Rational& r2,
                 const std::vector<detail::HalfPlane>& hs) {
  bool in_all = true;
  for (const auto& h : hs) in_all = in_all && inside(h, q);
  if (in_all) return false;
  std::vector<ExactPoint> candidates;
  for (std::size_t i = 0; i < hs.size(); ++i) {
    const ExactPoint p = project(hs[i], q);
    bool ok = true;
    for (std::size_t j = 0; j < hs.size(); ++j) ok = ok && (j == i || inside(hs[j], p));
    if (ok) candidates.push_back(p);
  }
  if (hs.size() == 2) {
    const Rational det = hs[0].a * hs[1].b - hs[1].a * hs[0].b;
    if (sgn(det) != 0) {
      candidates.push_back({(hs[0].c * hs[1].b - hs[1].c * hs[0].b) / det,
                            (hs[0].a * hs[1].c - hs[1].a * hs[0].c) / det});
    }
  }
  if (candidates.empty()) return false; // an empty wedge: not this certificate's business
  for (const auto& c : candidates) {
    if (squared_length(c, q) <= r2) return false;
  }
  return true;
}

// NO from the double outer candidate: the vertex of Q farthest from it, certified with the
// half-planes of the nearest edge or vertex.
// `witness` receives the vertex whose disk misses Π.
bool certified_no(const Ring& ring, const std::vector<PointD>& qd, const detail::ConvexCut& outer,
                  const Rational& outer_shift, const Rational& r2, std::size_t& witness) {
  const std::size_t m = outer.vertices.size();
  const double rd = std::sqrt(to_double(r2));
  // Farthest vertex of Q from the outer candidate (doubles choose).
  std::size_t best_i = 0;
  double best_d = -1;
  std::size_t best_edge = 0;
  for (std::size_t i = 0; i < qd.size(); ++i) {
    double dmin = INFINITY;
    std::size_t emin = 0;
    for (std::size_t k = 0; k < m; ++k) {
      const double d = detail::proposed_squared_distance(qd[i], outer.vertices[(k + m - 1) % m],
                                                         outer.vertices[k]);
      if (d < dmin) {
        dmin = d;
        emin = k;
      }
    }
    if (dmin > best_d) {
      best_d = dmin;
      best_i = i;
      best_edge = emin;
    }
  }
  if (std::sqrt(best_d) <= rd) return false;
  // Edge k of the cut runs from vertex k-1 to vertex k on plane edge_plane[k]; try that plane
  // alone, then with each neighbour (the nearest point may be a vertex).
  const std::size_t planes[3] = {outer.edge_plane[(best_edge + m - 1) % m],
                                 outer.edge_plane[best_edge],
                                 outer.edge_plane[(best_edge + 1) % m]};
  const detail::HalfPlane here = widened_half_plane(ring, planes[1], outer_shift);
  witness = best_i;
  if (disk_misses(ring[best_i], r2, {here})) return true;
  for (const std::size_t other : {planes[0], planes[2]}) {
    if (disk_misses(ring[best_i], r2, {here, widened_half_plane(ring, other, outer_shift)})) {
      return true;
    }
  }
  return false;
}

// The exact rational path (slow, always certified). With NO, `witness` is the vertex of Q whose
// disk misses Π (any vertex when Π is empty).
Answer exact_path(const Ring& ring, const DeconstructParams& params, const Rational& reach2,
                  const CancelHook& cancel, Ring& solution, std::size_t& witness) {
  const Rational shift = params.radius - params.tolerance;
  const Ring inner = detail::intersect_sorted_half_planes(
      detail::shifted_edge_half_planes(ring, shift, detail::ShiftBound::kUpper, kSqrtBits));
  if (!inner.empty() && first_vertex_missing(ring, inner, reach2, cancel) == ring.size()) {
    solution = inner;
    return Answer::kYes;
  }
  // Outer bracket with shift r - ε - δ/2: without interior it proves Π empty (Π is it inset by
  // a positive amount), as the paper's exterior approximation with D̄_{r-δ,r} would.
  const Rational outer_shift = shift - params.precision / 2;
  const auto bound =
      sgn(outer_shift) >= 0 ? detail::ShiftBound::kLower : detail::ShiftBound::kUpper;
  const Ring outer = detail::intersect_sorted_half_planes(
      detail::shifted_edge_half_planes(ring, outer_shift, bound, kSqrtBits));
  witness = 0;
  if (outer.empty()) return Answer::kNo;
  witness = first_vertex_missing(ring, outer, reach2, cancel);
  if (witness < ring.size()) return Answer::kNo;
  return Answer::kUndecided;
}

} // namespace

namespace {

// Encloses v in a one-ulp interval cheaply (no MPFR, no GMP arithmetic): get_d truncates towards
// zero, so v lies between it and its neighbour away from zero.
detail::IntervalNT enclose_truncated(const Rational& v) {
  const double d = v.get_d();
  const double away = std::nextafter(d, sgn(v) < 0 ? -HUGE_VAL : HUGE_VAL);
  return d < away ? detail::IntervalNT(d, away) : detail::IntervalNT(away, d);
}

detail::IPoint enclose_truncated(const ExactPoint& p) {
  return {enclose_truncated(p.x), enclose_truncated(p.y)};
}

// The turn a -> b -> c: intervals decide when they can (a repeated vertex never can: its
// enclosures coincide), exact rationals otherwise; nullopt for a repeated vertex.
std::optional<int> certified_turn(const detail::IPoint& u, const detail::IPoint& v,
                                  const detail::IPoint& w, const ExactPoint& a, const ExactPoint& b,
                                  const ExactPoint& c) {
  const detail::IntervalNT det = detail::orientation_determinant(u.x, u.y, v.x, v.y, w.x, w.y);
  if (det.inf() > 0) return 1;
  if (det.sup() < 0) return -1;
  if (a == b || b == c) return std::nullopt;
  return detail::orientation(a, b, c);
}

} // namespace

// One pass that stops at the first right turn (most inputs are not convex: the 200,000-vertex
// star stops after a few vertices), converting each vertex once, when the pass reaches it.
bool is_convex_region(const PolygonSet& q) {
  if (q.polygons.size() != 1 || !q.polygons[0].holes.empty()) return false;
  const Ring& ring = q.polygons[0].outer;
  const std::size_t n = ring.size();
  if (n < 3) return false;
  const CGAL::Protect_FPU_rounding<true> rounding;
  const detail::IPoint first = enclose_truncated(ring[0]);
  const detail::IPoint second = enclose_truncated(ring[1]);
  detail::IPoint u = first, v = second;
  bool any_turn = false;
  detail::IntervalNT twice_area(0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = i + 2;
    const detail::IPoint w = k < n ? enclose_truncated(ring[k]) : (k == n ? first : second);
    const auto turn = certified_turn(u, v, w, ring[i], ring[(i + 1) % n], ring[k % n]);
    if (!turn || *turn < 0) return false;
    any_turn |= *turn > 0;
    twice_area += u.x * v.y - u.y * v.x;
    u = v;
    v = w;
  }
  if (!any_turn) return false;
  // Left turns everywhere and a simple ring (validated by the caller) make a convex region;
  // the orientation rules out a clockwise ring that "turns right" as left.
  if (twice_area.inf() > 0) return true;
  if (twice_area.sup() < 0) return false;
  return sgn(twice_signed_area(ring)) > 0;
}

DeconstructResult convex_decide(const PolygonSet& q, const DeconstructParams& params,
                                const CancelHook& cancel) {
  if (!is_convex_region(q)) throw InvalidInput("convex_decide needs one convex polygon");
  if (params.radius <= params.tolerance) {
    throw InvalidInput("convex_decide needs r > ε (r <= ε is answered with P = Q)");
  }
  const auto start = std::chrono::steady_clock::now();
  const Ring& ring = q.polygons[0].outer;
  const Rational shift = params.radius - params.tolerance;
  const Rational reach = params.radius + params.tolerance;
  const Rational reach2 = reach * reach;

  DeconstructResult out;
  out.params = params;
  out.engine = params.engine;
  out.answer = Answer::kUndecided;

  std::vector<PointD> qd;
  qd.reserve(ring.size());
  double extent = to_double(reach);
  for (const auto& p : ring) {
    qd.push_back(to_double(p));
    extent = std::max({extent, std::abs(qd.back().x), std::abs(qd.back().y)});
  }
  // η only places the double candidate (a proposal); the checks below are certified.
  const double eta = std::max(1e-7 * extent, to_double(params.precision) / 1024);

  // YES: an inner candidate pushed in by η, proven inside Π, reached by every vertex disk.
  const detail::ConvexCut inner = detail::intersect_sorted_half_planes(
      detail::shifted_edge_half_planes(qd, to_double(shift) + eta));
  if (!inner.vertices.empty() && detail::convex_ring_inside_inset(inner.vertices, ring, shift)) {
    Ring inner_exact;
    for (const PointD& p : inner.vertices) inner_exact.push_back(exact(p));
    if (first_vertex_missing(ring, inner_exact, reach2, cancel) == ring.size()) {
      out.answer = Answer::kYes;
      out.solution.polygons.push_back({std::move(inner_exact), {}});
      out.hausdorff_bound = params.tolerance;
    }
  }
  if (out.answer != Answer::kYes) {
    // NO: the outer candidate at shift r - ε - δ/2 (a superset of Π, as the paper's exterior
    // approximation), certified by a vertex disk missing one or two widened half-planes.
    const Rational outer_shift = shift - params.precision / 2;
    const detail::ConvexCut outer = detail::intersect_sorted_half_planes(
        detail::shifted_edge_half_planes(qd, to_double(outer_shift)));
    std::size_t witness = 0;
    if (!outer.vertices.empty() && certified_no(ring, qd, outer, outer_shift, reach2, witness)) {
      out.answer = Answer::kNo;
      out.no_witness = ring[witness];
    } else {
      Ring solution;
      out.answer = exact_path(ring, params, reach2, cancel, solution, witness);
      if (out.answer == Answer::kNo) out.no_witness = ring[witness];
      if (out.answer == Answer::kYes) {
        out.solution.polygons.push_back({std::move(solution), {}});
        out.hausdorff_bound = params.tolerance;
      }
    }
  }
  out.elapsed = std::chrono::steady_clock::now() - start;
  return out;
}

DeconstructResult convex_decide_simplified(const PolygonSet& q, const DeconstructParams& params,
                                           const CancelHook& cancel) {
  const auto start = std::chrono::steady_clock::now();
  if (!is_convex_region(q)) throw InvalidInput("convex_decide needs one convex polygon");
  const Ring& ring = q.polygons[0].outer;
  const Rational sigma = params.precision / 4;
  const std::vector<std::size_t> keep = simplify_ring_indices(ring, sigma);
  const Rational& eps = params.tolerance;
  if (keep.size() == ring.size() || params.radius <= eps + sigma) {
    return convex_decide(q, params, cancel);
  }
  PolygonSet qs;
  qs.polygons.emplace_back();
  for (const std::size_t i : keep) qs.polygons[0].outer.push_back(ring[i]);
  auto finish = [&](DeconstructResult r) {
    r.params = params;
    r.elapsed = std::chrono::steady_clock::now() - start;
    if (r.answer == Answer::kYes) r.hausdorff_bound = eps;
    return r;
  };
  // δ/2 < ε - σ since σ = δ/4 < ε/4: the precondition holds for both calls.
  DeconstructParams tighter = params;
  tighter.tolerance = eps - sigma;
  tighter.precision = params.precision / 2;
  DeconstructResult yes = convex_decide(qs, tighter, cancel);
  if (yes.answer == Answer::kYes) return finish(std::move(yes));
  DeconstructParams looser = tighter;
  looser.tolerance = eps + sigma;
  DeconstructResult no = convex_decide(qs, looser, cancel);
  if (no.answer == Answer::kNo) return finish(std::move(no));
  return finish(convex_decide(q, params, cancel));
}

} // namespace penshape
