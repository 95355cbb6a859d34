// Calligraphy outlines to pen paths (the rule in outline_centerline.hpp).
#include "outline_centerline.hpp"

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

// The two chains from vertex 0 to vertex k (forward, and backward round the ring).
std::pair<std::vector<PointD>, std::vector<PointD>> chains(const std::vector<PointD>& ring,
                                                           std::size_t k) {
  std::vector<PointD> a(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(k) + 1);
  std::vector<PointD> b{ring[0]};
  for (std::size_t i = ring.size() - 1; i >= k; --i) b.push_back(ring[i]);
  return {a, b};
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

  constexpr std::size_t kPairs = 32;
  double best = std::numeric_limits<double>::infinity();
  std::size_t best_k = n / 2;
  for (std::size_t k = 2; k + 2 < n; ++k) {
    const auto [a, b] = chains(ring, k);
    const auto pa = resample(a, kPairs), pb = resample(b, kPairs);
    double cost = 0;
    // The ends meet at the cut points: only the inner pairs measure the width.
    for (std::size_t j = 2; j + 2 < kPairs; ++j) {
      const double w = std::hypot(pa[j].x - pb[j].x, pa[j].y - pb[j].y) - 2 * r;
      cost += w * w;
    }
    if (cost < best) best = cost, best_k = k;
  }
  const auto [a, b] = chains(ring, best_k);
  const std::size_t m = std::max<std::size_t>(kPairs, n / 2);
  const auto pa = resample(a, m), pb = resample(b, m);
  Centerline out;
  out.radius = r;
  for (std::size_t j = 0; j < m; ++j) {
    out.points.push_back({(pa[j].x + pb[j].x) / 2, (pa[j].y + pb[j].y) / 2});
  }
  return out;
}

} // namespace penshape::snap
