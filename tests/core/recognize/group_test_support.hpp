#pragma once
// Independent checks for grouped recognitions: the clean shape rebuilt from its parameters here
// (not with the recognizer's code) and a brute-force Hausdorff distance between it and the UNION
// of the strokes' paths.
#include <cmath>
#include <numbers>
#include <vector>

#include "penshape/core/group_recognize.hpp"

namespace penshape::test {

using Path = std::vector<PointD>;

inline double seg_dist(PointD p, PointD a, PointD b) {
  const double vx = b.x - a.x, vy = b.y - a.y, wx = p.x - a.x, wy = p.y - a.y;
  const double l2 = vx * vx + vy * vy;
  double t = l2 > 0 ? (wx * vx + wy * vy) / l2 : 0.0;
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  return std::hypot(wx - t * vx, wy - t * vy);
}

inline double path_dist(PointD p, const Path& path) {
  if (path.size() == 1) return std::hypot(p.x - path[0].x, p.y - path[0].y);
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    best = std::min(best, seg_dist(p, path[i], path[i + 1]));
  return best;
}

inline Path dense(const Path& path, double step) {
  Path out{path.front()};
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double len = std::hypot(path[i + 1].x - path[i].x, path[i + 1].y - path[i].y);
    const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
    for (int k = 1; k <= n; ++k) {
      const double f = static_cast<double>(k) / n;
      out.push_back({path[i].x + f * (path[i + 1].x - path[i].x),
                     path[i].y + f * (path[i + 1].y - path[i].y)});
    }
  }
  return out;
}

// Samples along a path (every 2 units), 10 ms apart from t0.
inline StrokeInput stroke_along(const Path& path, double t0, double pen_radius = 0.0) {
  StrokeInput in;
  in.pen_radius = pen_radius;
  double t = t0;
  for (const PointD& p : dense(path, 2.0)) {
    in.samples.push_back({p.x, p.y, t});
    t += 0.01;
  }
  return in;
}

// When the next stroke starts: 0.2 s after the last one ended.
inline double next_start(const std::vector<StrokeInput>& s) {
  return s.back().samples.back().t + 0.2;
}

// The arc through a, b and the point `bulge` to the left of their midpoint, from the
// circumcircle of the three points (fine chords).
inline Path arc_through(PointD a, PointD b, double bulge) {
  if (bulge == 0.0) return {a, b};
  const double c = std::hypot(b.x - a.x, b.y - a.y);
  const PointD u{(b.x - a.x) / c, (b.y - a.y) / c};
  const PointD m{(a.x + b.x) / 2 - bulge * u.y, (a.y + b.y) / 2 + bulge * u.x};
  const double d = 2 * (a.x * (m.y - b.y) + m.x * (b.y - a.y) + b.x * (a.y - m.y));
  const double a2 = a.x * a.x + a.y * a.y, m2 = m.x * m.x + m.y * m.y, b2 = b.x * b.x + b.y * b.y;
  const PointD o{(a2 * (m.y - b.y) + m2 * (b.y - a.y) + b2 * (a.y - m.y)) / d,
                 (a2 * (b.x - m.x) + m2 * (a.x - b.x) + b2 * (m.x - a.x)) / d};
  const double r = std::hypot(a.x - o.x, a.y - o.y);
  const double t0 = std::atan2(a.y - o.y, a.x - o.x), tm = std::atan2(m.y - o.y, m.x - o.x);
  double half = tm - t0;
  while (half > std::numbers::pi) half -= 2 * std::numbers::pi;
  while (half < -std::numbers::pi) half += 2 * std::numbers::pi;
  Path out;
  for (int k = 0; k <= 400; ++k) {
    const double t = t0 + 2 * half * k / 400.0;
    out.push_back({o.x + r * std::cos(t), o.y + r * std::sin(t)});
  }
  return out;
}

// The clean shape as paths (a set of polylines), rebuilt from the class and parameters.
inline std::vector<Path> clean_paths(const Recognition& r) {
  const ShapeParams& p = r.params;
  const std::vector<PointD>& v = p.vertices;
  switch (r.shape) {
    case ShapeClass::kCircle:
    case ShapeClass::kEllipse: {
      Path out;
      for (int k = 0; k <= 4096; ++k) {
        const double t = 2 * std::numbers::pi * k / 4096.0;
        const double x = p.radius_x * std::cos(t), y = p.radius_y * std::sin(t);
        out.push_back({p.center.x + std::cos(p.rotation) * x - std::sin(p.rotation) * y,
                       p.center.y + std::sin(p.rotation) * x + std::cos(p.rotation) * y});
      }
      return {out};
    }
    case ShapeClass::kArc: {
      Path out;
      for (int k = 0; k <= 4096; ++k) {
        const double t = p.start_angle + p.sweep_angle * k / 4096.0;
        out.push_back(
            {p.center.x + p.radius_x * std::cos(t), p.center.y + p.radius_x * std::sin(t)});
      }
      return {out};
    }
    case ShapeClass::kSegment:
    case ShapeClass::kPolyline:
      return {v};
    case ShapeClass::kArrow:
    case ShapeClass::kDoubleArrow: {
      // A bent shaft is the polyline through its bends; else the arc (or segment). A shaft that
      // stops short of the tip ends at shaft_end (the head is its own piece).
      const PointD stop = p.shaft_end.value_or(v[1]);
      Path shaft = arc_through(v[0], stop, p.shaft_bulge);
      if (!p.shaft_bends.empty()) {
        shaft = {v[0]};
        shaft.insert(shaft.end(), p.shaft_bends.begin(), p.shaft_bends.end());
        shaft.push_back(stop);
      }
      std::vector<Path> out{shaft, {v[1], v[2]}, {v[1], v[3]}};
      if (v.size() == 6) out.push_back({v[0], v[4]}), out.push_back({v[0], v[5]});
      return out;
    }
    default: {
      Path ring = v;
      ring.push_back(v.front());
      return {ring};
    }
  }
}

// Brute-force Hausdorff distance between the union of `strokes` and the union of `clean`.
inline double union_hausdorff(const std::vector<Path>& strokes, const std::vector<Path>& clean,
                              double step) {
  auto to_union = [](PointD q, const std::vector<Path>& set) {
    double best = INFINITY;
    for (const Path& p : set) best = std::min(best, path_dist(q, p));
    return best;
  };
  double worst = 0.0;
  for (const Path& s : strokes) {
    for (const PointD& q : dense(s, step)) worst = std::max(worst, to_union(q, clean));
  }
  for (const Path& c : clean) {
    for (const PointD& q : dense(c, step)) worst = std::max(worst, to_union(q, strokes));
  }
  return worst;
}

inline std::vector<Path> paths_of(const std::vector<StrokeInput>& strokes,
                                  const std::vector<std::size_t>& which) {
  std::vector<Path> out;
  for (const std::size_t i : which) {
    Path p;
    for (const StrokePoint& s : strokes[i].samples) p.push_back({s.x, s.y});
    out.push_back(p);
  }
  return out;
}

} // namespace penshape::test
