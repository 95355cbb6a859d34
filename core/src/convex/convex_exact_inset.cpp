#include "convex_exact_inset.hpp"

#include <deque>

namespace penshape::detail {
namespace {

// floor(sqrt(x) * 2^bits) / 2^bits and the next step up bracket sqrt(x) for rational x >= 0.
Rational sqrt_bound(const Rational& x, unsigned bits, ShiftBound bound) {
  // sqrt(N/D) = sqrt(N·D) / D; scale by 4^bits before the integer square root.
  mpz_class scaled = x.get_num() * x.get_den();
  mpz_mul_2exp(scaled.get_mpz_t(), scaled.get_mpz_t(), 2UL * bits);
  mpz_class root = sqrt(scaled); // floor
  if (bound == ShiftBound::kUpper && root * root != scaled) ++root;
  mpz_class den = x.get_den();
  mpz_mul_2exp(den.get_mpz_t(), den.get_mpz_t(), bits);
  Rational out(root, den);
  out.canonicalize();
  return out;
}

ExactPoint intersection(const HalfPlane& p, const HalfPlane& q) {
  const Rational det = p.a * q.b - q.a * p.b;
  return {(p.c * q.b - q.c * p.b) / det, (p.a * q.c - q.a * p.c) / det};
}

bool strictly_inside(const HalfPlane& h, const ExactPoint& p) {
  return h.a * p.x + h.b * p.y < h.c;
}

Rational cross(const HalfPlane& p, const HalfPlane& q) { return p.a * q.b - q.a * p.b; }

Rational dot(const HalfPlane& p, const HalfPlane& q) { return p.a * q.a + p.b * q.b; }

} // namespace

std::vector<HalfPlane> shifted_edge_half_planes(const Ring& ring, const Rational& shift,
                                                ShiftBound bound, unsigned precision_bits) {
  std::vector<HalfPlane> out;
  const std::size_t n = ring.size();
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ExactPoint& p = ring[i];
    const ExactPoint& q = ring[(i + 1) % n];
    // Counterclockwise ring: the outward normal of edge p→q is (dy, -dx).
    HalfPlane h{q.y - p.y, p.x - q.x, 0};
    h.c = h.a * p.x + h.b * p.y;
    const Rational norm = sqrt_bound(h.a * h.a + h.b * h.b, precision_bits, bound);
    h.c -= shift * norm;
    out.push_back(std::move(h));
  }
  return out;
}

Ring intersect_sorted_half_planes(const std::vector<HalfPlane>& planes) {
  std::deque<HalfPlane> dq;
  for (const HalfPlane& h : planes) {
    if (!dq.empty() && sgn(cross(dq.back(), h)) == 0 && sgn(dot(dq.back(), h)) > 0) {
      // Same direction: keep the more restrictive. h = λ·back with λ > 0 on (a, b).
      const Rational lambda =
          sgn(h.a) != 0 ? Rational(h.a / dq.back().a) : Rational(h.b / dq.back().b);
      if (h.c < lambda * dq.back().c) dq.back() = h;
      continue;
    }
    while (dq.size() >= 2 &&
           !strictly_inside(h, intersection(dq[dq.size() - 1], dq[dq.size() - 2]))) {
      dq.pop_back();
    }
    while (dq.size() >= 2 && !strictly_inside(h, intersection(dq[0], dq[1]))) dq.pop_front();
    if (!dq.empty() && sgn(cross(dq.back(), h)) <= 0) {
      // Turning by π or more: opposite or reflex directions mean an empty intersection
      // (for a convex ring's edges this only happens once everything else collapsed).
      return {};
    }
    dq.push_back(h);
  }
  while (dq.size() >= 3 &&
         !strictly_inside(dq.front(), intersection(dq[dq.size() - 1], dq[dq.size() - 2]))) {
    dq.pop_back();
  }
  while (dq.size() >= 3 && !strictly_inside(dq.back(), intersection(dq[0], dq[1]))) dq.pop_front();
  if (dq.size() < 3) return {};
  // The last and first planes must also turn left, or the region is unbounded / empty.
  if (sgn(cross(dq.back(), dq.front())) <= 0) return {};
  Ring out;
  out.reserve(dq.size());
  for (std::size_t i = 0; i < dq.size(); ++i) {
    out.push_back(intersection(dq[i], dq[(i + 1) % dq.size()]));
  }
  if (sgn(twice_signed_area(out)) <= 0) return {};
  return out;
}

} // namespace penshape::detail
