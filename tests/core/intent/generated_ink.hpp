#pragma once
// Handwriting-like and drawn strokes the project generates itself (millimetres, y down, t in
// seconds), so that a bare clone can test the writing/drawing decision: cursive words as loops
// along a baseline (letters ~5 mm, some ascenders), i-dots and t-bars, on lines 10 mm apart;
// shapes of 20-60 mm (circle, rectangle, triangle, segment, arrow) drawn between the lines.
#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::test::ink {

using Points = std::vector<StrokePoint>;

struct PageStroke {
  Points points;
  bool writing = true;
};

// Points along a polyline at about 0.5 mm steps, 100 samples a second, starting at time t.
inline Points traced(const std::vector<std::pair<double, double>>& corners, double& t) {
  Points out;
  for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
    const auto [x0, y0] = corners[i];
    const auto [x1, y1] = corners[i + 1];
    const int n = std::max(1, static_cast<int>(std::hypot(x1 - x0, y1 - y0) / 0.5));
    for (int k = i == 0 ? 0 : 1; k <= n; ++k) {
      const double u = static_cast<double>(k) / n;
      out.push_back({x0 + u * (x1 - x0), y0 + u * (y1 - y0), t});
      t += 0.01;
    }
  }
  return out;
}

// A cursive word of `letters` loops whose baseline starts at (x, y).
inline Points cursive_word(double x, double y, int letters, std::mt19937& rng, double& t) {
  std::uniform_real_distribution<double> jitter(0.85, 1.15);
  std::uniform_int_distribution<int> ascender(0, 4);
  std::vector<std::pair<double, double>> path;
  double cx = x;
  for (int l = 0; l < letters; ++l) {
    const double h = (ascender(rng) == 0 ? 9.0 : 4.5) * jitter(rng);
    const double w = 2.8 * jitter(rng);
    for (int k = 0; k <= 16; ++k) {
      const double u = 2 * std::numbers::pi * k / 16;
      path.emplace_back(cx + w * u / (2 * std::numbers::pi) - 1.2 * std::sin(u),
                        y - 0.5 * h * (1 - std::cos(u)));
    }
    cx += w;
  }
  return traced(path, t);
}

inline Points circle(double cx, double cy, double r, double& t) {
  std::vector<std::pair<double, double>> path;
  for (int k = 0; k <= 72; ++k) {
    const double u = 2 * std::numbers::pi * k / 72;
    path.emplace_back(cx + r * std::cos(u), cy + r * std::sin(u));
  }
  return traced(path, t);
}

inline std::vector<Points> shapes_at(double x, double y, double& t) {
  return {circle(x + 15, y + 15, 15, t),
          traced({{x + 40, y}, {x + 80, y}, {x + 80, y + 25}, {x + 40, y + 25}, {x + 40, y}}, t),
          traced({{x + 95, y + 30}, {x + 115, y}, {x + 135, y + 30}, {x + 95, y + 30}}, t),
          traced({{x + 145, y + 15}, {x + 185, y + 15}}, t),
          traced({{x + 10, y + 50},
                  {x + 50, y + 50},
                  {x + 44, y + 45},
                  {x + 50, y + 50},
                  {x + 44, y + 55}},
                 t)};
}

// A page of notes: `lines` lines of cursive words with i-dots and t-bars; with `shapes`, the
// five shapes drawn below every second line.
inline std::vector<PageStroke> note_page(int lines, bool shapes, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> letters(2, 6);
  std::vector<PageStroke> page;
  double t = 0, y = 30;
  for (int line = 0; line < lines; ++line) {
    for (double x = 20; x < 160;) {
      const int n = letters(rng);
      Points word = cursive_word(x, y, n, rng, t);
      const double width = word.back().x - x;
      page.push_back({std::move(word), true});
      t += 0.2;
      if (n > 3) page.push_back({{{x + 4, y - 7, t}}, true}); // an i-dot
      t += 0.2;
      if (n > 4) page.push_back({traced({{x + 7, y - 5}, {x + 10, y - 5.2}}, t), true});
      t += 0.3;
      x += width + 4;
    }
    y += 10;
    if (shapes && line % 2 == 1) {
      for (Points& s : shapes_at(20, y + 2, t)) page.push_back({std::move(s), false});
      t += 1;
      y += 70;
    }
  }
  return page;
}

} // namespace penshape::test::ink
