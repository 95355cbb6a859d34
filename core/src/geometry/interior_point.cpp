// interior_point(): exact rational arithmetic throughout (interior_point.hpp).
#include "geometry/interior_point.hpp"

#include <algorithm>
#include <vector>

namespace penshape::detail {
namespace {

// The widest interval of a polygon on the line through its widest gap between vertex heights.
std::optional<std::pair<Rational, ExactPoint>> widest_cut(const PolygonWithHoles& poly) {
  std::vector<const Ring*> rings{&poly.outer};
  for (const auto& h : poly.holes) rings.push_back(&h);
  std::vector<Rational> ys;
  for (const auto& p : poly.outer) ys.push_back(p.y);
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  std::optional<std::pair<Rational, ExactPoint>> best;
  // Try a few lines (the widest vertical gaps of the outer ring; holes may still hit them).
  std::vector<std::pair<Rational, Rational>> gaps;
  for (std::size_t i = 0; i + 1 < ys.size(); ++i) gaps.emplace_back(ys[i + 1] - ys[i], ys[i]);
  std::sort(gaps.begin(), gaps.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  if (gaps.size() > 8) gaps.resize(8);
  for (const auto& [gap, y0] : gaps) {
    const Rational y = y0 + gap / 2;
    std::vector<Rational> xs;
    bool through_vertex = false;
    for (const Ring* ring : rings) {
      for (std::size_t i = 0; i < ring->size(); ++i) {
        const ExactPoint& a = (*ring)[i];
        const ExactPoint& b = (*ring)[(i + 1) % ring->size()];
        if (a.y == y) through_vertex = true;
        if ((a.y < y) == (b.y < y)) continue;
        xs.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
      }
    }
    if (through_vertex || xs.size() < 2) continue;
    std::sort(xs.begin(), xs.end());
    for (std::size_t i = 0; i + 1 < xs.size(); i += 2) {
      const Rational w = xs[i + 1] - xs[i];
      if (sgn(w) > 0 && (!best || w > best->first)) {
        best = {{w, ExactPoint{(xs[i] + xs[i + 1]) / 2, y}}};
      }
    }
  }
  return best;
}

} // namespace

std::optional<ExactPoint> interior_point(const PolygonSet& set) {
  std::optional<ExactPoint> out;
  Rational best_area = 0;
  for (const auto& poly : set.polygons) {
    Rational a = abs(twice_signed_area(poly.outer));
    for (const auto& h : poly.holes) a -= abs(twice_signed_area(h));
    if (out && a <= best_area) continue;
    if (const auto cut = widest_cut(poly)) {
      out = cut->second;
      best_area = a;
    }
  }
  return out;
}

} // namespace penshape::detail
