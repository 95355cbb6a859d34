#pragma once
// Brute-force oracles for the annulus tests, written independently of core/src/annulus: the
// annulus measure by direct distance formulas, placements enumerated as all pairwise
// intersections of the boundary lines and circles of the containing regions (Lemma 3), and
// triple-contact placements for rotation. Cubic to quartic in n: small inputs only.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "penshape/core/polygon_set.hpp"

namespace penshape::annulus::oracle {

enum class Kind { kRound, kLinearized, kSimple };

struct Pose {
  double tx = 0, ty = 0, theta = 0;
};

inline double seg_dist(PointD x, PointD a, PointD b) {
  const double vx = b.x - a.x, vy = b.y - a.y;
  double t = ((x.x - a.x) * vx + (x.y - a.y) * vy) / (vx * vx + vy * vy);
  t = std::max(0.0, std::min(1.0, t));
  return std::hypot(x.x - a.x - t * vx, x.y - a.y - t * vy);
}

// Least delta whose annulus holds x (template frame; poly counterclockwise).
inline double measure(const std::vector<PointD>& poly, Kind kind, PointD x) {
  double boundary = INFINITY;
  double line_max = -INFINITY; // signed distance to the edge lines, outside positive
  const std::size_t m = poly.size();
  for (std::size_t k = 0; k < m; ++k) {
    const PointD a = poly[k], b = poly[(k + 1) % m];
    boundary = std::min(boundary, seg_dist(x, a, b));
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    line_max = std::max(line_max, ((b.y - a.y) * (x.x - a.x) - (b.x - a.x) * (x.y - a.y)) / len);
  }
  if (kind == Kind::kSimple) return boundary;
  if (line_max <= 0) return boundary; // inside a convex polygon: distance to the boundary
  return kind == Kind::kLinearized ? line_max : boundary;
}

inline PointD to_template(const Pose& p, PointD q) {
  const double c = std::cos(p.theta), s = std::sin(p.theta);
  const double dx = q.x - p.tx, dy = q.y - p.ty;
  return {c * dx + s * dy, -s * dx + c * dy};
}

inline std::size_t count(const std::vector<PointD>& poly, Kind kind, double delta, const Pose& p,
                         const std::vector<PointD>& pts, double tol = 1e-9) {
  std::size_t c = 0;
  for (const PointD& q : pts) c += measure(poly, kind, to_template(p, q)) <= delta + tol ? 1 : 0;
  return c;
}

// Boundary carriers of one containing region in translation space: lines n.t = c, circles.
struct Line {
  double nx, ny, c;
};
struct Circle {
  double x, y, r;
};

inline void carriers(const std::vector<PointD>& poly, Kind kind, double delta, PointD q,
                     std::vector<Line>& lines, std::vector<Circle>& circles) {
  const std::size_t m = poly.size();
  for (std::size_t k = 0; k < m; ++k) {
    const PointD a = poly[k], b = poly[(k + 1) % m];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const double nx = (b.y - a.y) / len, ny = -(b.x - a.x) / len;
    const double h = nx * a.x + ny * a.y;
    // template point x = q - t on the line n.x = h + s  <=>  n.t = n.q - h - s
    for (double s : {delta, -delta}) lines.push_back({nx, ny, nx * q.x + ny * q.y - h - s});
    if (kind != Kind::kLinearized) circles.push_back({q.x - a.x, q.y - a.y, delta});
  }
}

inline std::vector<PointD> candidates(const std::vector<PointD>& poly, Kind kind, double delta,
                                      const std::vector<PointD>& pts) {
  std::vector<Line> L;
  std::vector<Circle> C;
  for (const PointD& q : pts) carriers(poly, kind, delta, q, L, C);
  std::vector<PointD> out;
  for (std::size_t i = 0; i < L.size(); ++i) {
    for (std::size_t j = i + 1; j < L.size(); ++j) {
      const double det = L[i].nx * L[j].ny - L[i].ny * L[j].nx;
      if (std::abs(det) < 1e-12) continue;
      out.push_back({(L[i].c * L[j].ny - L[i].ny * L[j].c) / det,
                     (L[i].nx * L[j].c - L[i].c * L[j].nx) / det});
    }
    for (const Circle& c : C) {
      // foot of the centre on the line, then +- along it
      const double dist = L[i].nx * c.x + L[i].ny * c.y - L[i].c;
      if (std::abs(dist) > c.r) continue;
      const double fx = c.x - dist * L[i].nx, fy = c.y - dist * L[i].ny;
      const double h = std::sqrt(std::max(0.0, c.r * c.r - dist * dist));
      out.push_back({fx - h * L[i].ny, fy + h * L[i].nx});
      out.push_back({fx + h * L[i].ny, fy - h * L[i].nx});
    }
  }
  for (std::size_t i = 0; i < C.size(); ++i) {
    out.push_back({C[i].x, C[i].y + C[i].r});
    for (std::size_t j = i + 1; j < C.size(); ++j) {
      const double dx = C[j].x - C[i].x, dy = C[j].y - C[i].y;
      const double d = std::hypot(dx, dy);
      if (d == 0 || d > C[i].r + C[j].r) continue;
      const double a = (C[i].r * C[i].r - C[j].r * C[j].r + d * d) / (2 * d);
      const double h = std::sqrt(std::max(0.0, C[i].r * C[i].r - a * a));
      const double mx = C[i].x + a * dx / d, my = C[i].y + a * dy / d;
      out.push_back({mx - h * dy / d, my + h * dx / d});
      out.push_back({mx + h * dy / d, my - h * dx / d});
    }
  }
  return out;
}

inline std::size_t max_cover_translation(const std::vector<PointD>& poly, Kind kind, double delta,
                                         const std::vector<PointD>& pts, double theta = 0) {
  // Rotating the points by -theta about the origin is the same as rotating the template by theta.
  std::vector<PointD> rp;
  rp.reserve(pts.size());
  const double c = std::cos(theta), s = std::sin(theta);
  for (const PointD& q : pts) rp.push_back({c * q.x + s * q.y, -s * q.x + c * q.y});
  std::size_t best = 0;
  for (const PointD& t : candidates(poly, kind, delta, rp)) {
    best = std::max(best, count(poly, kind, delta, Pose{t.x, t.y, 0}, rp));
  }
  return best;
}

inline double min_width_translation(const std::vector<PointD>& poly, Kind kind,
                                    const std::vector<PointD>& pts, double hi) {
  double lo = 0;
  while (hi - lo > 1e-10 * (1 + hi)) {
    const double mid = 0.5 * (lo + hi);
    (max_cover_translation(poly, kind, mid, pts) == pts.size() ? hi : lo) = mid;
  }
  return hi;
}

// Rotation (linearized): every placement with three (point, edge line) contacts.
inline std::size_t max_cover_rotation(const std::vector<PointD>& poly, double delta,
                                      const std::vector<PointD>& pts) {
  struct Con {
    std::size_t q;
    double nx, ny, c; // n . R(-theta)(q - t) = c
  };
  std::vector<Con> cons;
  const std::size_t m = poly.size();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    for (std::size_t k = 0; k < m; ++k) {
      const PointD a = poly[k], b = poly[(k + 1) % m];
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      const double nx = (b.y - a.y) / len, ny = -(b.x - a.x) / len;
      for (double s : {delta, -delta}) cons.push_back({i, nx, ny, nx * a.x + ny * a.y + s});
    }
  }
  std::size_t best = 0;
  auto eval = [&](double theta, double tpx, double tpy) {
    // t' = R(-theta) t
    const double c = std::cos(theta), s = std::sin(theta);
    const Pose p{c * tpx - s * tpy, s * tpx + c * tpy, theta};
    best = std::max(best, count(poly, Kind::kLinearized, delta, p, pts));
  };
  for (std::size_t a = 0; a < cons.size(); ++a) {
    for (std::size_t b = a + 1; b < cons.size(); ++b) {
      for (std::size_t e = b + 1; e < cons.size(); ++e) {
        const Con* K[3] = {&cons[a], &cons[b], &cons[e]};
        // c*alpha + s*beta - n.t' = c_  with alpha = n.q, beta = n.(qy, -qx)
        double al[3], be[3];
        for (int r = 0; r < 3; ++r) {
          const PointD q = pts[K[r]->q];
          al[r] = K[r]->nx * q.x + K[r]->ny * q.y;
          be[r] = K[r]->nx * q.y - K[r]->ny * q.x;
        }
        // lambda orthogonal to both columns of N (rows n_r)
        const double l0 = K[1]->nx * K[2]->ny - K[2]->nx * K[1]->ny;
        const double l1 = K[2]->nx * K[0]->ny - K[0]->nx * K[2]->ny;
        const double l2 = K[0]->nx * K[1]->ny - K[1]->nx * K[0]->ny;
        const double A = l0 * al[0] + l1 * al[1] + l2 * al[2];
        const double B = l0 * be[0] + l1 * be[1] + l2 * be[2];
        const double Cc = l0 * K[0]->c + l1 * K[1]->c + l2 * K[2]->c;
        const double R = std::hypot(A, B);
        if (R < 1e-12 || std::abs(Cc) > R) continue;
        const double psi = std::atan2(B, A), alpha = std::acos(Cc / R);
        for (double theta : {psi + alpha, psi - alpha}) {
          const double c = std::cos(theta), s = std::sin(theta);
          // two rows with independent normals give t'
          for (int r1 = 0; r1 < 3; ++r1) {
            const int r2 = (r1 + 1) % 3;
            const double det = K[r1]->nx * K[r2]->ny - K[r1]->ny * K[r2]->nx;
            if (std::abs(det) < 1e-9) continue;
            const double b1 = c * al[r1] + s * be[r1] - K[r1]->c;
            const double b2 = c * al[r2] + s * be[r2] - K[r2]->c;
            eval(theta, (b1 * K[r2]->ny - K[r1]->ny * b2) / det,
                 (K[r1]->nx * b2 - b1 * K[r2]->nx) / det);
            break;
          }
        }
      }
    }
  }
  // Sampled angles with the exact translation oracle (covers degenerate optima).
  for (int k = 0; k < 180; ++k) {
    best = std::max(best, max_cover_translation(poly, Kind::kLinearized, delta, pts,
                                                2 * std::numbers::pi * k / 180));
  }
  return best;
}

// Random strictly convex polygon with m vertices around the origin, radius about r.
inline std::vector<PointD> random_convex(std::mt19937& rng, std::size_t m, double r) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> ang(m);
  for (std::size_t attempt = 0;; ++attempt) {
    for (auto& a : ang) a = 2 * std::numbers::pi * u(rng);
    std::sort(ang.begin(), ang.end());
    bool ok = true;
    for (std::size_t k = 0; k < m; ++k) {
      const double gap = k + 1 < m ? ang[k + 1] - ang[k] : ang[0] + 2 * std::numbers::pi - ang[k];
      ok = ok && gap > 0.3 && gap < 2.6;
    }
    if (ok || attempt > 1000) break;
  }
  const double sx = r * (0.6 + 0.8 * u(rng)), sy = r * (0.6 + 0.8 * u(rng));
  std::vector<PointD> v;
  v.reserve(ang.size());
  for (double a : ang) v.push_back({sx * std::cos(a), sy * std::sin(a)});
  return v;
}

// Points near the boundary of the polygon placed at (tx, ty) rotated by theta, with noise.
inline std::vector<PointD> points_near(std::mt19937& rng, const std::vector<PointD>& poly,
                                       std::size_t n, double noise, Pose pose,
                                       double outlier_fraction = 0.0) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<PointD> pts;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k =
        static_cast<std::size_t>(u(rng) * static_cast<double>(poly.size())) % poly.size();
    const PointD a = poly[k], b = poly[(k + 1) % poly.size()];
    const double t = u(rng);
    double x = a.x + t * (b.x - a.x) + noise * (2 * u(rng) - 1);
    double y = a.y + t * (b.y - a.y) + noise * (2 * u(rng) - 1);
    if (u(rng) < outlier_fraction) {
      x = 3 * (2 * u(rng) - 1);
      y = 3 * (2 * u(rng) - 1);
    }
    pts.push_back({c * x - s * y + pose.tx, s * x + c * y + pose.ty});
  }
  return pts;
}

} // namespace penshape::annulus::oracle
