#include "convex_inset.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "geometry/exact_predicates.hpp"

namespace penshape::detail {
namespace {

PointD intersection(const HalfPlaneD& p, const HalfPlaneD& q) {
  const double det = p.a * q.b - q.a * p.b;
  return {(p.c * q.b - q.c * p.b) / det, (p.a * q.c - q.a * p.c) / det};
}

bool strictly_inside(const HalfPlaneD& h, PointD p) { return h.a * p.x + h.b * p.y < h.c; }

double cross(const HalfPlaneD& p, const HalfPlaneD& q) { return p.a * q.b - q.a * p.b; }

} // namespace

std::vector<HalfPlaneD> shifted_edge_half_planes(const std::vector<PointD>& ring, double shift) {
  std::vector<HalfPlaneD> out;
  const std::size_t n = ring.size();
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const PointD p = ring[i];
    const PointD q = ring[(i + 1) % n];
    HalfPlaneD h{q.y - p.y, p.x - q.x, 0};
    const double len = std::hypot(h.a, h.b);
    h.a /= len; // unit normals keep the deque's comparisons well scaled
    h.b /= len;
    h.c = h.a * p.x + h.b * p.y - shift;
    out.push_back(h);
  }
  return out;
}

ConvexCut intersect_sorted_half_planes(const std::vector<HalfPlaneD>& planes) {
  std::deque<HalfPlaneD> dq;
  std::deque<std::size_t> ids; // mirrors dq: each plane's index in `planes`
  for (std::size_t id = 0; id < planes.size(); ++id) {
    const HalfPlaneD& h = planes[id];
    if (!dq.empty() && std::abs(cross(dq.back(), h)) < 1e-15 &&
        dq.back().a * h.a + dq.back().b * h.b > 0) {
      if (h.c < dq.back().c) { // parallel, same direction: the tighter one
        dq.back() = h;
        ids.back() = id;
      }
      continue;
    }
    while (dq.size() >= 2 &&
           !strictly_inside(h, intersection(dq[dq.size() - 1], dq[dq.size() - 2]))) {
      dq.pop_back();
      ids.pop_back();
    }
    while (dq.size() >= 2 && !strictly_inside(h, intersection(dq[0], dq[1]))) {
      dq.pop_front();
      ids.pop_front();
    }
    if (!dq.empty() && cross(dq.back(), h) <= 0) return {};
    dq.push_back(h);
    ids.push_back(id);
  }
  while (dq.size() >= 3 &&
         !strictly_inside(dq.front(), intersection(dq[dq.size() - 1], dq[dq.size() - 2]))) {
    dq.pop_back();
    ids.pop_back();
  }
  while (dq.size() >= 3 && !strictly_inside(dq.back(), intersection(dq[0], dq[1]))) {
    dq.pop_front();
    ids.pop_front();
  }
  if (dq.size() < 3 || cross(dq.back(), dq.front()) <= 0) return {};
  ConvexCut out;
  out.vertices.reserve(dq.size());
  for (std::size_t i = 0; i < dq.size(); ++i) {
    const PointD p = intersection(dq[i], dq[(i + 1) % dq.size()]);
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return {};
    out.vertices.push_back(p);
  }
  out.edge_plane.assign(ids.begin(), ids.end());
  return out;
}

bool convex_ring_inside_inset(const std::vector<PointD>& pi, const Ring& q, const Rational& shift) {
  const std::size_t m = pi.size();
  const std::size_t n = q.size();
  if (m < 3 || n < 3) return false;
  double extent = 0;
  for (const PointD& p : pi) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
  std::vector<PointD> qd;
  qd.reserve(n);
  for (const auto& p : q) {
    qd.push_back(to_double(p));
    extent = std::max({extent, std::abs(qd.back().x), std::abs(qd.back().y)});
  }
  // Doubles decide what they clear by a margin far above their rounding (about 1e-16 of the
  // magnitudes involved); exact rationals decide the rest.
  const double rel = 1e-10;
  // Strictly convex and counterclockwise: then n·v is unimodal along the ring.
  for (std::size_t i = 0; i < m; ++i) {
    const PointD a = pi[i];
    const PointD b = pi[(i + 1) % m];
    const PointD c = pi[(i + 2) % m];
    if (orientation(a, b, c) <= 0) return false; // the kernel's filtered exact predicate
  }
  const double shift_d = to_double(shift);
  std::size_t j = 0; // the vertex extreme along the current edge normal; turns with the edges
  for (std::size_t i = 0; i < n; ++i) {
    const PointD p = qd[i];
    const PointD s = qd[(i + 1) % n];
    const double a = s.y - p.y;
    const double b = p.x - s.x;
    auto height = [&](std::size_t k) { return a * pi[k % m].x + b * pi[k % m].y; };
    if (i == 0) {
      for (std::size_t k = 1; k < m; ++k) {
        if (height(k) > height(j)) j = k;
      }
    } else {
      for (std::size_t steps = 0; steps < m && height(j + 1) > height(j); ++steps) j = (j + 1) % m;
    }
    const double len = std::hypot(a, b);
    const double gap = a * p.x + b * p.y - height(j);
    if (gap - shift_d * len > rel * len * (extent + shift_d)) continue; // clear in doubles
    // Too close for doubles: the exact test on this vertex and its neighbours (the true extreme
    // is among them: doubles only mistake near-ties).
    const ExactPoint& ep = q[i];
    const ExactPoint& es = q[(i + 1) % n];
    const Rational ea = es.y - ep.y;
    const Rational eb = ep.x - es.x;
    const Rational ec = ea * ep.x + eb * ep.y;
    const Rational need = shift * shift * (ea * ea + eb * eb);
    for (const std::size_t k : {j + m - 1, j, j + 1}) {
      const ExactPoint v = exact(pi[k % m]);
      const Rational g = ec - ea * v.x - eb * v.y;
      if (sgn(g) < 0 || g * g < need) return false;
    }
  }
  return true;
}

} // namespace penshape::detail
