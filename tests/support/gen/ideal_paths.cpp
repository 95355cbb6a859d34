// Ideal paths for the stroke generator (see ideal_paths.hpp).
#include "ideal_paths.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace penshape::gen {
namespace {

constexpr double kTau = 2 * std::numbers::pi;

// Cursive lowercase letters as control points in x-height units (y up from the baseline),
// each entering at the left near the baseline and leaving at the right: a hand's letter shapes.
const std::array<std::vector<Pt>, 8>& letter_shapes() {
  static const std::array<std::vector<Pt>, 8> shapes{{
      {{0, 0.2}, {0.8, 0.8}, {0.5, 1}, {0.1, 0.6}, {0.2, 0.1}, {0.6, 0}, {0.9, 0.2}},       // c
      {{0, 0.3}, {0.7, 0.55}, {0.6, 0.95}, {0.2, 0.9}, {0.05, 0.4}, {0.3, 0}, {0.8, 0.15}}, // e
      {{0, 0.2}, {0.5, 1.5}, {0.5, 2.1}, {0.2, 1.8}, {0.25, 0.5}, {0.4, 0}, {0.8, 0.2}},    // l
      {{0, 0.3},
       {0.5, 1},
       {0.1, 0.6},
       {0.25, 0},
       {0.7, 0.1},
       {0.75, 0.8},
       {0.5, 1},
       {0.95, 0.85}}, // o
      {{0, 0},
       {0.15, 0.9},
       {0.2, 0.7},
       {0.25, 0},
       {0.35, 0.8},
       {0.6, 0.95},
       {0.7, 0.5},
       {0.75, 0},
       {1.0, 0.2}},                                                          // n
      {{0, 0.9}, {0.1, 0.1}, {0.4, 0}, {0.6, 0.9}, {0.65, 0.2}, {0.9, 0.1}}, // u
      {{0, 0.3},
       {0.7, 0.8},
       {0.4, 1},
       {0.05, 0.5},
       {0.25, 0},
       {0.65, 0.5},
       {0.7, 0.95},
       {0.7, 0.1},
       {1.0, 0.15}},                                                                  // a
      {{0, 0.1}, {0.5, 1}, {0.3, 0.6}, {0.7, 0.3}, {0.4, 0}, {0.1, 0.1}, {0.8, 0.1}}, // s
  }};
  return shapes;
}

Pt catmull_rom(Pt p0, Pt p1, Pt p2, Pt p3, double u) {
  const double u2 = u * u, u3 = u2 * u;
  auto f = [&](double a, double b, double c, double d) {
    return 0.5 * (2 * b + (-a + c) * u + (2 * a - 5 * b + 4 * c - d) * u2 +
                  (-a + 3 * b - 3 * c + d) * u3);
  };
  return {f(p0.x, p1.x, p2.x, p3.x), f(p0.y, p1.y, p2.y, p3.y)};
}

} // namespace

std::vector<Pt> closed_outline(const std::vector<Pt>& vertices, std::size_t start, double gap) {
  const std::size_t n = vertices.size();
  std::vector<Pt> out;
  for (std::size_t k = 0; k <= n; ++k) out.push_back(vertices[(start + k) % n]);
  const Pt first = out.front(), second = out[1];
  if (gap < 0) { // overshoot along the first edge
    const double len = std::hypot(second.x - first.x, second.y - first.y);
    const double u = std::min(-gap / len, 0.5);
    out.push_back({first.x + u * (second.x - first.x), first.y + u * (second.y - first.y)});
    return out;
  }
  // Stop `gap` short of the start, along the last edge.
  const Pt prev = out[n - 1];
  const double len = std::hypot(first.x - prev.x, first.y - prev.y);
  const double u = std::min(gap / len, 0.5);
  out.back() = {first.x + u * (prev.x - first.x), first.y + u * (prev.y - first.y)};
  return out;
}

std::vector<Pt> elliptic_arc(Pt centre, double a, double b, double rotation, double from,
                             double sweep) {
  const int steps = std::max(8, static_cast<int>(std::fabs(sweep) / kTau * 96));
  std::vector<Pt> out;
  const double c = std::cos(rotation), s = std::sin(rotation);
  for (int k = 0; k <= steps; ++k) {
    const double t = from + sweep * k / steps;
    const double x = a * std::cos(t), y = b * std::sin(t);
    out.push_back({centre.x + c * x - s * y, centre.y + s * x + c * y});
  }
  return out;
}

std::vector<Pt> spiral(Pt centre, double radius, double turns, bool clockwise) {
  const int steps = static_cast<int>(turns * 64);
  std::vector<Pt> out;
  for (int k = 0; k <= steps; ++k) {
    const double f = static_cast<double>(k) / steps;
    const double t = (clockwise ? -1 : 1) * kTau * turns * f;
    out.push_back({centre.x + radius * f * std::cos(t), centre.y + radius * f * std::sin(t)});
  }
  return out;
}

std::vector<Pt> scribble(Pt centre, double size, int count, Rng& rng) {
  std::vector<Pt> pts;
  pts.reserve(static_cast<std::size_t>(std::max(count, 0)));
  for (int k = 0; k < count; ++k) {
    pts.push_back(
        {centre.x + size * rng.uniform(-0.5, 0.5), centre.y + size * rng.uniform(-0.5, 0.5)});
  }
  return smooth_through(pts, 12);
}

std::vector<Pt> cursive_word(Pt origin, double height, int letters, Rng& rng) {
  std::vector<Pt> control;
  double x = origin.x;
  for (int k = 0; k < letters; ++k) {
    const auto& shape = letter_shapes()[static_cast<std::size_t>(rng.integer(0, 7))];
    const double slant = rng.uniform(0.1, 0.35), width = rng.uniform(0.8, 1.2);
    for (const Pt& p : shape) {
      const double px = x + height * (width * p.x + slant * p.y) + rng.normal(0, 0.03 * height);
      control.push_back({px, origin.y - height * p.y + rng.normal(0, 0.03 * height)});
    }
    x += height * (width + 0.15);
  }
  return smooth_through(control, 8);
}

std::vector<Pt> smooth_through(const std::vector<Pt>& points, int per_span) {
  if (points.size() < 2) return points;
  std::vector<Pt> out;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Pt p0 = points[i == 0 ? 0 : i - 1], p1 = points[i], p2 = points[i + 1];
    const Pt p3 = points[std::min(i + 2, points.size() - 1)];
    for (int k = 0; k < per_span; ++k)
      out.push_back(catmull_rom(p0, p1, p2, p3, k * 1.0 / per_span));
  }
  out.push_back(points.back());
  return out;
}

} // namespace penshape::gen
