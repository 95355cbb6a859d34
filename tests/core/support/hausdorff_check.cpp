#include "support/hausdorff_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace penshape::test {
namespace {

double segment_distance(PointD p, PointD a, PointD b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

bool inside_rings(const std::vector<std::vector<PointD>>& rings, PointD p) {
  bool in = false;
  for (const auto& ring : rings) {
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      const PointD a = ring[i];
      const PointD b = ring[j];
      if ((a.y > p.y) != (b.y > p.y)) {
        const double x = b.x + (p.y - b.y) * (a.x - b.x) / (a.y - b.y);
        if (p.x < x) in = !in;
      }
    }
  }
  return in;
}

double distance_to_edges(const std::vector<std::vector<PointD>>& chains, bool closed, PointD p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& c : chains) {
    if (c.size() == 1) best = std::min(best, std::hypot(p.x - c[0].x, p.y - c[0].y));
    const std::size_t m = closed ? c.size() : c.size() - 1;
    for (std::size_t i = 0; i < m && c.size() > 1; ++i) {
      best = std::min(best, segment_distance(p, c[i], c[(i + 1) % c.size()]));
    }
  }
  return best;
}

double distance_to_skeleton(const SkeletonD& s, PointD p) {
  if (!s.closed_rings.empty() && inside_rings(s.closed_rings, p)) return 0.0;
  return std::min(distance_to_edges(s.closed_rings, true, p),
                  distance_to_edges(s.polylines, false, p));
}

// Samples every `spacing` along the chains' edges (both ends included).
std::vector<PointD> edge_samples(const std::vector<std::vector<PointD>>& chains, bool closed,
                                 double spacing) {
  std::vector<PointD> out;
  for (const auto& c : chains) {
    if (c.size() == 1) out.push_back(c[0]);
    const std::size_t m = closed ? c.size() : c.size() - 1;
    for (std::size_t i = 0; i < m && c.size() > 1; ++i) {
      const PointD a = c[i];
      const PointD b = c[(i + 1) % c.size()];
      const int steps =
          std::max(1, static_cast<int>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / spacing)));
      for (int k = 0; k <= steps; ++k) {
        const double t = static_cast<double>(k) / steps;
        out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
      }
    }
  }
  return out;
}

void extend_box(const std::vector<std::vector<PointD>>& chains, double& x0, double& y0, double& x1,
                double& y1) {
  for (const auto& c : chains) {
    for (const auto& p : c) {
      x0 = std::min(x0, p.x);
      y0 = std::min(y0, p.y);
      x1 = std::max(x1, p.x);
      y1 = std::max(y1, p.y);
    }
  }
}

std::vector<PointD> ring_d(const Ring& ring) {
  std::vector<PointD> out;
  out.reserve(ring.size());
  for (const auto& v : ring) out.push_back(to_double(v));
  return out;
}

} // namespace

RegionD to_region_d(const PolygonSet& set) {
  RegionD q;
  for (const auto& p : set.polygons) {
    q.rings.push_back(ring_d(p.outer));
    for (const auto& h : p.holes) q.rings.push_back(ring_d(h));
  }
  return q;
}

SkeletonD region_skeleton(const PolygonSet& set) { return {to_region_d(set).rings, {}}; }

double distance_to_region(const RegionD& q, PointD p) {
  if (inside_rings(q.rings, p)) return 0.0;
  return distance_to_edges(q.rings, true, p);
}

HausdorffEstimate hausdorff_to_offset(const SkeletonD& s, double r, const RegionD& q,
                                      double spacing) {
  const double inf = std::numeric_limits<double>::infinity();
  double x0 = inf, y0 = inf, x1 = -inf, y1 = -inf;
  extend_box(s.closed_rings, x0, y0, x1, y1);
  extend_box(s.polylines, x0, y0, x1, y1);
  x0 -= r + spacing;
  y0 -= r + spacing;
  x1 += r + spacing;
  y1 += r + spacing;
  extend_box(q.rings, x0, y0, x1, y1);

  double q_to_offset = 0.0; // sup over Q of the distance to offset(S, r)
  double offset_to_q = 0.0; // sup over offset(S, r) of the distance to Q
  for (double y = y0; y <= y1 + spacing; y += spacing) {
    for (double x = x0; x <= x1 + spacing; x += spacing) {
      const PointD g{x, y};
      const double ds = distance_to_skeleton(s, g);
      if (inside_rings(q.rings, g)) {
        q_to_offset = std::max(q_to_offset, ds - r);
      } else if (ds <= r + spacing) {
        offset_to_q = std::max(offset_to_q, distance_to_edges(q.rings, true, g));
      }
    }
  }
  for (const PointD& p : edge_samples(q.rings, true, spacing)) {
    q_to_offset = std::max(q_to_offset, distance_to_skeleton(s, p) - r);
  }
  std::vector<PointD> skeleton_points = edge_samples(s.closed_rings, true, spacing);
  for (const PointD& p : edge_samples(s.polylines, false, spacing)) skeleton_points.push_back(p);
  // A few points exactly on the offset boundary sharpen the estimate; the grid alone already
  // gives the bound.
  const int directions = 8;
  for (const PointD& p : skeleton_points) {
    for (int k = 0; k < directions; ++k) {
      const double a = 2 * std::numbers::pi * k / directions;
      const PointD y{p.x + r * std::cos(a), p.y + r * std::sin(a)};
      offset_to_q = std::max(offset_to_q, distance_to_region(q, y));
    }
  }
  // A point of Q is within h/sqrt(2) of a grid point inside Q, or within h/sqrt(2) of ∂Q and so
  // within h/sqrt(2) + h/2 < 1.25·h of a boundary sample; the offset side is within h.
  return {std::max(q_to_offset, offset_to_q), 1.25 * spacing};
}

} // namespace penshape::test
