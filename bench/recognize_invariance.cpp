// The recognizer's answers under transforms of the drawing and of the device
// (recognize_invariance.hpp).
#include "recognize_invariance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>
#include <set>
#include <string>

#include "penshape/core/recognize.hpp"
#include "recognize_accuracy.hpp"

namespace penshape::bench {
namespace {

using Points = std::vector<StrokePoint>;
// A transform sees the stroke, its size (bounding-box diagonal) and a seeded generator.
using Apply = std::function<Points(const Points&, double, std::mt19937_64&)>;

struct Transform {
  std::string name;
  Apply apply;
};

double size_of(const Points& p) {
  auto [x0, x1] =
      std::minmax_element(p.begin(), p.end(), [](auto& a, auto& b) { return a.x < b.x; });
  auto [y0, y1] =
      std::minmax_element(p.begin(), p.end(), [](auto& a, auto& b) { return a.y < b.y; });
  return std::hypot(x1->x - x0->x, y1->y - y0->y);
}

Points each_point(Points p, const std::function<void(StrokePoint&)>& f) {
  for (StrokePoint& q : p) f(q);
  return p;
}

Points rotated(const Points& p, double degrees) {
  const double c = std::cos(degrees * std::numbers::pi / 180.0);
  const double s = std::sin(degrees * std::numbers::pi / 180.0);
  return each_point(p, [c, s](StrokePoint& q) { q = {c * q.x - s * q.y, s * q.x + c * q.y, q.t}; });
}

// Drawn from its end to its start, the time still running forward.
Points backwards(const Points& p) {
  Points out(p.rbegin(), p.rend());
  const double end = p.back().t;
  for (StrokePoint& q : out) q.t = end - q.t;
  return out;
}

// Every n-th sample and the last: a device sampling n times more slowly.
Points every_nth(const Points& p, std::size_t n) {
  Points out;
  for (std::size_t i = 0; i < p.size(); i += n) out.push_back(p[i]);
  if ((p.size() - 1) % n != 0) out.push_back(p.back());
  return out;
}

// n samples per step, interpolated in position and time: a device sampling n times faster.
Points interpolated(const Points& p, std::size_t n) {
  Points out;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    for (std::size_t k = 0; k < n; ++k) {
      const double w = static_cast<double>(k) / static_cast<double>(n);
      out.push_back({p[i].x + w * (p[i + 1].x - p[i].x), p[i].y + w * (p[i + 1].y - p[i].y),
                     p[i].t + w * (p[i + 1].t - p[i].t)});
    }
  }
  out.push_back(p.back());
  return out;
}

Points jittered(const Points& p, double amplitude, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  return each_point(p, [&](StrokePoint& q) { q.x += u(rng), q.y += u(rng); });
}

Points on_grid(const Points& p, double step) {
  return each_point(p, [step](StrokePoint& q) {
    q.x = step * std::round(q.x / step), q.y = step * std::round(q.y / step);
  });
}

std::vector<Transform> drawing_transforms() {
  std::vector<Transform> t;
  const auto add = [&t](std::string name, Apply f) {
    t.push_back({std::move(name), std::move(f)});
  };
  add("moved by 10^6", [](const Points& p, double, auto&) {
    return each_point(p, [](StrokePoint& q) { q.x += 1e6, q.y -= 1e6; });
  });
  for (const double k : {0.01, 1000.0}) {
    add("scaled by " + std::to_string(k).substr(0, 6), [k](const Points& p, double, auto&) {
      return each_point(p, [k](StrokePoint& q) { q.x *= k, q.y *= k; });
    });
  }
  add("time in ms", [](const Points& p, double, auto&) {
    return each_point(p, [](StrokePoint& q) { q.t *= 1000.0; });
  });
  add("no time", [](const Points& p, double, auto&) {
    return each_point(p, [](StrokePoint& q) { q.t = 0.0; });
  });
  for (const double d : {10.0, 30.0, 45.0, 90.0, 180.0}) {
    add("turned by " + std::to_string(static_cast<int>(d)) + " deg",
        [d](const Points& p, double, auto&) { return rotated(p, d); });
  }
  add("mirrored", [](const Points& p, double, auto&) {
    return each_point(p, [](StrokePoint& q) { q.x = -q.x; });
  });
  add("drawn backwards", [](const Points& p, double, auto&) { return backwards(p); });
  return t;
}

std::vector<Transform> device_transforms() {
  std::vector<Transform> t;
  const auto add = [&t](std::string name, Apply f) {
    t.push_back({std::move(name), std::move(f)});
  };
  for (const std::size_t n : {2U, 3U}) {
    add("1/" + std::to_string(n) + " of the sample rate",
        [n](const Points& p, double, auto&) { return every_nth(p, n); });
  }
  add("4 x the sample rate", [](const Points& p, double, auto&) { return interpolated(p, 4); });
  for (const double f : {0.005, 0.01}) {
    add("jitter +-" + std::to_string(f * 100).substr(0, 3) + "% of the size",
        [f](const Points& p, double size, auto& rng) { return jittered(p, f * size, rng); });
    add("grid of " + std::to_string(f * 100).substr(0, 3) + "% of the size",
        [f](const Points& p, double size, auto&) { return on_grid(p, f * size); });
  }
  add("4 x the rate, grid of 0.5%", [](const Points& p, double size, auto&) {
    return on_grid(interpolated(p, 4), 0.005 * size);
  });
  return t;
}

struct Labelled {
  const Points* points;
  const std::set<std::string>* targets; // null: a non-shape
  std::string as_drawn;                 // the class recognize() names the drawing itself
};

std::string class_of(const Points& p) {
  try {
    return to_string(recognize(p).shape);
  } catch (const InvalidInput&) {
    return "refused"; // counted as no snap and as a changed answer
  }
}

std::vector<Labelled> labelled_strokes(const std::vector<Drawing>& drawings) {
  std::vector<Labelled> out;
  for (const auto& [drawing, targets] : single_stroke_samples(drawings)) {
    const Points& p = drawing->strokes.front();
    out.push_back({&p, targets, class_of(p)});
  }
  return out;
}

struct Row {
  int shapes = 0, right = 0, non_shapes = 0, snapped = 0, changed = 0;
  void add(const Labelled& l, const std::string& got) {
    if (l.targets != nullptr) {
      ++shapes, right += l.targets->contains(got) ? 1 : 0;
    } else {
      ++non_shapes, snapped += got != "freeform" && got != "dot" && got != "refused" ? 1 : 0;
    }
    changed += got != l.as_drawn ? 1 : 0;
  }
};

void print_row(const std::string& name, const Row& r) {
  const auto pct = [](int a, int b) { return b > 0 ? 100.0 * a / b : 0.0; };
  std::printf("  %-34s %6.1f%%  %6.1f%%  %6.1f%%\n", name.c_str(), pct(r.right, r.shapes),
              pct(r.snapped, r.non_shapes), pct(r.changed, r.shapes + r.non_shapes));
}

void print_rows(const std::vector<Labelled>& strokes, const std::vector<Transform>& transforms) {
  for (const Transform& t : transforms) {
    std::mt19937_64 rng(2026); // the same jitter for every run
    Row row;
    for (const Labelled& l : strokes) {
      row.add(l, class_of(t.apply(*l.points, size_of(*l.points), rng)));
    }
    print_row(t.name, row);
    std::fflush(stdout);
  }
}

} // namespace

void print_invariance(const std::vector<Drawing>& drawings) {
  const std::vector<Labelled> strokes = labelled_strokes(drawings);
  if (strokes.empty()) return;
  Row as_drawn;
  for (const Labelled& l : strokes) as_drawn.add(l, l.as_drawn);
  std::printf("\ninvariance: %zu labelled single strokes ($1 logs and gestures)\n", strokes.size());
  std::printf("  %-34s %7s  %7s  %7s\n", "transform", "shapes", "non-sh.", "answers");
  std::printf("  %-34s %7s  %7s  %7s\n", "", "right", "snapped", "changed");
  print_row("as drawn", as_drawn);
  std::printf(
      " the drawing moved, scaled, retimed (nothing may change), turned, mirrored, reversed:\n");
  print_rows(strokes, drawing_transforms());
  std::printf(" as other devices would send it (jitter and grid relative to the stroke's size):\n");
  print_rows(strokes, device_transforms());
}

} // namespace penshape::bench
