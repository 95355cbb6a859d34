// CONVEXDECIDE (Algorithm 6) with rational inner and outer brackets of Π.
#include <chrono>

#include "convex_inset.hpp"
#include "penshape/core/convex_deconstruct.hpp"

namespace penshape {
namespace {

// |n| is bracketed to a relative 2^-kSqrtBits: the brackets of Π differ by about
// (r - ε)·2^-kSqrtBits, far below any δ a caller can ask for.
constexpr unsigned kSqrtBits = 64;

// For each vertex q_i of Q (counterclockwise), is some edge of the convex ring `pi` within
// distance R? Walks the edges from where the previous vertex found one (Lemma 23's linear scan);
// a full loop without success answers for that vertex exactly. Returns the index of the first
// vertex that fails, or q.size() when all succeed.
std::size_t first_vertex_missing(const Ring& q, const Ring& pi, const Rational& r_squared,
                                 const CancelHook& cancel) {
  const std::size_t m = pi.size();
  std::size_t edge = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    if ((i & 63U) == 0 && cancel && cancel()) throw Cancelled();
    bool found = false;
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t e = (edge + k) % m;
      if (detail::squared_distance_to_segment(q[i], pi[e], pi[(e + 1) % m]) <= r_squared) {
        edge = e;
        found = true;
        break;
      }
    }
    if (!found) return i;
  }
  return q.size();
}

} // namespace

bool is_convex_region(const PolygonSet& q) {
  if (q.polygons.size() != 1 || !q.polygons[0].holes.empty()) return false;
  const Ring& ring = q.polygons[0].outer;
  const std::size_t n = ring.size();
  if (n < 3) return false;
  bool any_turn = false;
  for (std::size_t i = 0; i < n; ++i) {
    const ExactPoint& a = ring[i];
    const ExactPoint& b = ring[(i + 1) % n];
    const ExactPoint& c = ring[(i + 2) % n];
    const int turn = sgn((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x));
    if (turn < 0) return false;
    any_turn |= turn > 0;
  }
  // Left turns everywhere and a simple ring (validated by the caller) make a convex region;
  // the orientation check rules out a clockwise ring that "turns right" as left.
  return any_turn && sgn(twice_signed_area(ring)) > 0;
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

  const Ring inner = detail::intersect_sorted_half_planes(
      detail::shifted_edge_half_planes(ring, shift, detail::ShiftBound::kUpper, kSqrtBits));
  if (!inner.empty() && first_vertex_missing(ring, inner, reach2, cancel) == ring.size()) {
    out.answer = Answer::kYes;
    out.solution.polygons.push_back({inner, {}});
    out.hausdorff_bound = params.tolerance;
  } else {
    // The outer bracket uses the shift r - ε - δ/2: then an outer region without interior
    // proves Π empty (Π is that region inset by a positive amount), a certified NO, as the
    // paper's exterior approximation with D̄_{r-δ,r} would.
    const Rational outer_shift = shift - params.precision / 2;
    // A superset needs a shift of at most outer_shift·|n|: the lower bound of |n| when the
    // shift is inward, the upper one when it is outward.
    const auto bound =
        sgn(outer_shift) >= 0 ? detail::ShiftBound::kLower : detail::ShiftBound::kUpper;
    const Ring outer = detail::intersect_sorted_half_planes(
        detail::shifted_edge_half_planes(ring, outer_shift, bound, kSqrtBits));
    if (outer.empty() || first_vertex_missing(ring, outer, reach2, cancel) < ring.size()) {
      out.answer = Answer::kNo;
    }
  }
  out.elapsed = std::chrono::steady_clock::now() - start;
  return out;
}

} // namespace penshape
