// Calligraphy outlines to pen paths (the rule in outline_centerline.hpp).
#include "outline_centerline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace penshape::snap {
namespace {

// m points at equal arc-length steps along the chain (first and last included).
std::vector<PointD> resample(const std::vector<PointD>& chain, std::size_t m) {
  std::vector<double> acc{0.0};
  for (std::size_t i = 1; i < chain.size(); ++i) {
    acc.push_back(acc.back() +
                  std::hypot(chain[i].x - chain[i - 1].x, chain[i].y - chain[i - 1].y));
  }
  std::vector<PointD> out;
  std::size_t seg = 1;
  for (std::size_t j = 0; j < m; ++j) {
    const double s = acc.back() * static_cast<double>(j) / static_cast<double>(m - 1);
    while (seg + 1 < chain.size() && acc[seg] < s) ++seg;
    const double len = acc[seg] - acc[seg - 1];
    const double t = len > 0 ? std::clamp((s - acc[seg - 1]) / len, 0.0, 1.0) : 0.0;
    out.push_back({chain[seg - 1].x + t * (chain[seg].x - chain[seg - 1].x),
                   chain[seg - 1].y + t * (chain[seg].y - chain[seg - 1].y)});
  }
  return out;
}

// The two chains from vertex a to vertex k: forward round the ring, and backward.
std::pair<std::vector<PointD>, std::vector<PointD>> chains(const std::vector<PointD>& ring,
                                                           std::size_t a, std::size_t k) {
  const std::size_t n = ring.size();
  std::vector<PointD> fwd, back;
  for (std::size_t i = a;; i = (i + 1) % n) {
    fwd.push_back(ring[i]);
    if (i == k) break;
  }
  for (std::size_t i = a;; i = (i + n - 1) % n) {
    back.push_back(ring[i]);
    if (i == k) break;
  }
  return {fwd, back};
}

constexpr std::size_t kPairs = 32;

// Least-squares misfit of the pairs' distances to the pen's width 2r (the inner pairs only: the
// ends meet at the cut points).
double cut_cost(const std::vector<PointD>& ring, std::size_t a, std::size_t k, double r) {
  const auto [fwd, back] = chains(ring, a, k);
  if (fwd.size() < 3 || back.size() < 3) return std::numeric_limits<double>::infinity();
  const auto pa = resample(fwd, kPairs), pb = resample(back, kPairs);
  double cost = 0;
  for (std::size_t j = 2; j + 2 < kPairs; ++j) {
    const double w = std::hypot(pa[j].x - pb[j].x, pa[j].y - pb[j].y) - 2 * r;
    cost += w * w;
  }
  return cost;
}

// The best second cut for a fixed first one.
std::size_t best_cut(const std::vector<PointD>& ring, std::size_t fixed, double r) {
  double best = std::numeric_limits<double>::infinity();
  std::size_t at = (fixed + ring.size() / 2) % ring.size();
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (i == fixed) continue;
    const double c = cut_cost(ring, fixed, i, r);
    if (c < best) best = c, at = i;
  }
  return at;
}

// The path without its first and last `len` of arc length (the caps' share: a cut sits on a
// cap's rim, r beyond the stroke's end).
std::vector<PointD> trimmed(const std::vector<PointD>& path, double len) {
  double total = 0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    total += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
  }
  if (total <= 4 * len) return path;
  const std::size_t m = path.size();
  std::vector<PointD> out;
  const auto all = resample(path, 4 * m);
  double s = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (i > 0) s += std::hypot(all[i].x - all[i - 1].x, all[i].y - all[i - 1].y);
    if (s >= len && s <= total - len) out.push_back(all[i]);
  }
  return out.size() >= 2 ? out : path;
}

} // namespace

std::optional<Centerline> outline_centerline(const std::vector<PointD>& ring) {
  const std::size_t n = ring.size();
  if (n < 6) return std::nullopt;
  double area2 = 0, perimeter = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const PointD& p = ring[i];
    const PointD& q = ring[(i + 1) % n];
    area2 += p.x * q.y - q.x * p.y;
    perimeter += std::hypot(q.x - p.x, q.y - p.y);
  }
  const double area = std::abs(area2) / 2;
  const double disc = perimeter * perimeter - 4 * std::numbers::pi * area;
  if (!(disc >= 0) || !(area > 0)) return std::nullopt;
  const double r = (perimeter - std::sqrt(disc)) / (2 * std::numbers::pi);
  if (!(r > 0)) return std::nullopt;

  // The outline starts near the stroke's start (Inkscape's does): cut there, find the far cut,
  // then move the first cut to where it fits best against the far one.
  const std::size_t k = best_cut(ring, 0, r);
  const std::size_t a = best_cut(ring, k, r);
  const auto [fwd, back] = chains(ring, a, k);
  const std::size_t m = std::max<std::size_t>(kPairs, n / 2);
  const auto pa = resample(fwd, m), pb = resample(back, m);
  std::vector<PointD> mid;
  for (std::size_t j = 0; j < m; ++j) {
    mid.push_back({(pa[j].x + pb[j].x) / 2, (pa[j].y + pb[j].y) / 2});
  }
  Centerline out;
  out.radius = r;
  out.points = trimmed(mid, r);
  return out;
}

} // namespace penshape::snap
