// EdgeSet: a uniform grid over a polygon set's edges with exact queries (verify_edges.hpp).
#include "verify/verify_edges.hpp"

#include <algorithm>
#include <cmath>

namespace penshape::verify {
namespace {

double segment_distance2(double x, double y, double ax, double ay, double bx, double by) {
  const double ux = bx - ax;
  const double uy = by - ay;
  const double len2 = ux * ux + uy * uy;
  double t = len2 > 0 ? ((x - ax) * ux + (y - ay) * uy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double dx = x - (ax + t * ux);
  const double dy = y - (ay + t * uy);
  return dx * dx + dy * dy;
}

} // namespace

EdgeSet::EdgeSet(const PolygonSet& set, double typical_query) {
  for (const auto& poly : set.polygons) {
    std::vector<const Ring*> rings{&poly.outer};
    for (const auto& h : poly.holes) rings.push_back(&h);
    for (const Ring* ring : rings) {
      const auto first = static_cast<std::uint32_t>(points_.size());
      const auto n = static_cast<std::uint32_t>(ring->size());
      for (const auto& p : *ring) points_.push_back(vpoint(p));
      for (std::uint32_t i = 0; i < n; ++i) edges_.push_back({first + i, first + (i + 1) % n});
    }
  }
  if (points_.empty()) return;
  low_ = high_ = points_.front().e;
  for (const auto& p : points_) {
    if (p.e.x < low_.x) low_.x = p.e.x;
    if (p.e.y < low_.y) low_.y = p.e.y;
    if (p.e.x > high_.x) high_.x = p.e.x;
    if (p.e.y > high_.y) high_.y = p.e.y;
    px_.push_back(p.e.x.get_d());
    py_.push_back(p.e.y.get_d());
  }
  x0_ = low_.x.get_d();
  y0_ = low_.y.get_d();
  const double w = std::max(high_.x.get_d() - x0_, high_.y.get_d() - y0_);
  const double magnitude = std::max(
      {std::abs(x0_), std::abs(y0_), std::abs(high_.x.get_d()), std::abs(high_.y.get_d())});
  // Doubles of the vertices and of query points are within 2^-52 relative of the rationals;
  // this pad is millions of times wider, so padded boxes contain the exact ones.
  pad_ = 1e-9 * (magnitude + w) + 1e-300;
  const double n = static_cast<double>(edges_.size());
  cell_ = std::max({w / std::max(1.0, std::sqrt(n)), typical_query / 2.0, w / 2048.0, pad_});
  cols_ = static_cast<std::size_t>((high_.x.get_d() - x0_) / cell_) + 1;
  rows_ = static_cast<std::size_t>((high_.y.get_d() - y0_) / cell_) + 1;
  cells_.assign(cols_ * rows_, {});
  strips_.assign(rows_, {});
  stamp_.assign(edges_.size(), 0);
  const double reach = cell_ * 0.7072 + pad_;
  for (std::uint32_t e = 0; e < edges_.size(); ++e) {
    const double ax = px_[edges_[e].a], ay = py_[edges_[e].a];
    const double bx = px_[edges_[e].b], by = py_[edges_[e].b];
    const std::size_t r0 = row(std::min(ay, by) - pad_), r1 = row(std::max(ay, by) + pad_);
    const std::size_t c0 = col(std::min(ax, bx) - pad_), c1 = col(std::max(ax, bx) + pad_);
    for (std::size_t r = r0; r <= r1; ++r) {
      strips_[r].push_back(e);
      for (std::size_t c = c0; c <= c1; ++c) {
        const double cx = x0_ + (static_cast<double>(c) + 0.5) * cell_;
        const double cy = y0_ + (static_cast<double>(r) + 0.5) * cell_;
        if (segment_distance2(cx, cy, ax, ay, bx, by) <= reach * reach) {
          cells_[r * cols_ + c].push_back(e);
        }
      }
    }
  }
}

std::size_t EdgeSet::col(double x) const {
  const double c = std::floor((x - x0_) / cell_);
  if (!(c > 0)) return 0;
  return std::min(cols_ - 1, static_cast<std::size_t>(c));
}

std::size_t EdgeSet::row(double y) const {
  const double r = std::floor((y - y0_) / cell_);
  if (!(r > 0)) return 0;
  return std::min(rows_ - 1, static_cast<std::size_t>(r));
}

// Calls f(edge index) once for every edge that may have a point within `reach` of (x, y) (a
// superset: every edge with such a point is visited). Stops when f returns true; returns
// whether it did.
template <typename F>
bool EdgeSet::for_edges_near(double x, double y, double reach, F&& f) const {
  if (edges_.empty()) return false;
  const double d = reach + pad_ + 1e-9 * (std::abs(x) + std::abs(y));
  if (x + d < x0_ - pad_ || y + d < y0_ - pad_) return false;
  if (x - d > x0_ + static_cast<double>(cols_) * cell_ + pad_) return false;
  if (y - d > y0_ + static_cast<double>(rows_) * cell_ + pad_) return false;
  ++epoch_;
  if (epoch_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0);
    epoch_ = 1;
  }
  const std::size_t r0 = row(y - d), r1 = row(y + d), c0 = col(x - d), c1 = col(x + d);
  for (std::size_t r = r0; r <= r1; ++r) {
    for (std::size_t c = c0; c <= c1; ++c) {
      for (const std::uint32_t e : cells_[r * cols_ + c]) {
        if (stamp_[e] == epoch_) continue;
        stamp_[e] = epoch_;
        if (f(e)) return true;
      }
    }
  }
  return false;
}

bool EdgeSet::contains(const VPoint& c) const {
  if (edges_.empty()) return false;
  const double y = c.e.y.get_d();
  if (y < y0_ - pad_ || y > y0_ + static_cast<double>(rows_) * cell_ + pad_) return false;
  bool inside = false;
  for (const std::uint32_t e : strips_[row(y)]) {
    const VPoint& a = points_[edges_[e].a];
    const VPoint& b = points_[edges_[e].b];
    // Edges wholly left of c cannot cross the ray towards +x.
    if (a.x.sup() < c.x.inf() && b.x.sup() < c.x.inf()) continue;
    if (crosses_ray(a, b, c)) inside = !inside;
  }
  return inside;
}

bool EdgeSet::any_within(const VPoint& c, const Threshold& l) const {
  return for_edges_near(c.e.x.get_d(), c.e.y.get_d(), l.approx, [&](std::uint32_t e) {
    return compare_distance(c, points_[edges_[e].a], points_[edges_[e].b], l) <= 0;
  });
}

bool EdgeSet::all_beyond(const VPoint& c, const Threshold& l) const {
  return !for_edges_near(c.e.x.get_d(), c.e.y.get_d(), l.approx, [&](std::uint32_t e) {
    return compare_distance(c, points_[edges_[e].a], points_[edges_[e].b], l) <= 0;
  });
}

double EdgeSet::approx_distance(double x, double y, double cap) const {
  double best = cap * cap;
  for_edges_near(x, y, cap, [&](std::uint32_t e) {
    const auto& g = edges_[e];
    best = std::min(best, segment_distance2(x, y, px_[g.a], py_[g.a], px_[g.b], py_[g.b]));
    return false;
  });
  return std::sqrt(best);
}

std::vector<EdgeSet::Segment> EdgeSet::edges_near(double x, double y, double reach) const {
  std::vector<Segment> out;
  for_edges_near(x, y, reach, [&](std::uint32_t e) {
    out.emplace_back(&points_[edges_[e].a], &points_[edges_[e].b]);
    return false;
  });
  return out;
}

std::optional<EdgeSet::Segment> EdgeSet::approx_nearest_edge(double x, double y, double cap) const {
  double best = cap * cap;
  std::optional<Segment> out;
  for_edges_near(x, y, cap, [&](std::uint32_t e) {
    const auto& g = edges_[e];
    const double d2 = segment_distance2(x, y, px_[g.a], py_[g.a], px_[g.b], py_[g.b]);
    if (d2 <= best) {
      best = d2;
      out = Segment{&points_[g.a], &points_[g.b]};
    }
    return false;
  });
  return out;
}

bool EdgeSet::approx_contains(double x, double y) const {
  if (edges_.empty()) return false;
  if (y < y0_ || y > y0_ + static_cast<double>(rows_) * cell_) return false;
  bool inside = false;
  for (const std::uint32_t e : strips_[row(y)]) {
    const double ax = px_[edges_[e].a], ay = py_[edges_[e].a];
    const double bx = px_[edges_[e].b], by = py_[edges_[e].b];
    if ((ay <= y) == (by <= y)) continue;
    const double t = (y - ay) / (by - ay);
    if (ax + t * (bx - ax) > x) inside = !inside;
  }
  return inside;
}

} // namespace penshape::verify
