// Corner seeds from the deconstruction's skeleton (see skeleton_seeds.hpp).
#include "recognize/fitting/skeleton_seeds.hpp"

#include <cmath>

namespace penshape::recognize_detail {

std::vector<PointD> skeleton_corners(const PolygonSet& skeleton, std::size_t k) {
  const PolygonWithHoles* largest = nullptr;
  Rational best_area = 0;
  for (const PolygonWithHoles& p : skeleton.polygons) {
    Rational a = twice_signed_area(p.outer);
    if (a < 0) a = -a;
    if (!largest || a > best_area) {
      largest = &p;
      best_area = a;
    }
  }
  if (!largest || largest->outer.size() < k || k < 3) return {};
  std::vector<PointD> ring;
  ring.reserve(largest->outer.size());
  for (const ExactPoint& v : largest->outer) ring.push_back(to_double(v));
  while (ring.size() > k) {
    std::size_t weakest = 0;
    double weakest_d = INFINITY;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const PointD prev = ring[(i + ring.size() - 1) % ring.size()];
      const PointD next = ring[(i + 1) % ring.size()];
      const double d = segment_distance(ring[i], prev, next);
      if (d < weakest_d) {
        weakest_d = d;
        weakest = i;
      }
    }
    ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(weakest));
  }
  return ring;
}

void apply_skeleton_seeds(const PreparedStroke& s, const PolygonSet& skeleton,
                          std::vector<Fit>& fits) {
  auto replace_if_better = [&fits](Fit f) {
    for (Fit& old : fits) {
      if (old.shape != f.shape) continue;
      if (f.fit_error < old.fit_error) old = std::move(f);
      return;
    }
    fits.push_back(std::move(f));
  };
  for (const std::size_t k : {std::size_t{3}, std::size_t{4}}) {
    const std::vector<PointD> corners = skeleton_corners(skeleton, k);
    if (corners.size() != k) continue;
    std::optional<Fit> seeded = fit_polygon_from_corners(s, corners);
    if (!seeded || !std::isfinite(seeded->fit_error)) continue;
    if (k == 4) {
      for (Fit& f : fit_rectangles(s, *seeded)) {
        if (std::isfinite(f.fit_error)) replace_if_better(std::move(f));
      }
    }
    replace_if_better(std::move(*seeded));
  }
}

} // namespace penshape::recognize_detail
