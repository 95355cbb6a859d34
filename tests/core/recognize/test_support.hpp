#pragma once
// Test helpers for the recognizer, written independently of the recognizer's code: a $1 log
// reader, the stroke corpus (the real $1 logs of the shared corpus, else the generated stand-in
// laid out the same way), and an independent Hausdorff check of a snap.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "dollar_xml.hpp"
#include "generated_corpus.hpp"
#include "penshape/core/recognize.hpp"
#include "test_data.hpp"

namespace penshape::test {

// The reading of the $1 gestures: a shape gesture counts as correct for these classes;
// the non-shape gestures must stay freeform (star is excluded).
inline const std::map<std::string, std::set<std::string>> kShapeTargets{
    {"circle", {"circle", "ellipse"}},
    {"rectangle", {"rectangle", "square", "quadrilateral"}},
    {"triangle", {"triangle"}},
};
// The $1 non-shape gestures, and the generator's non-shapes (never $1 names). The generator's
// dots are left out: a 2-pixel mark is a segment to the recognizer, a case of its own.
inline const std::set<std::string> kNonShapes{
    "pigtail",     "question_mark", "left_curly_brace", "right_curly_brace",
    "delete_mark", "scribble",      "spiral",           "letter",
    "word"};

// Rows: gesture names; columns: the classes given; cells: counts.
using ConfusionTable = std::map<std::string, std::map<std::string, int>>;

inline void print_confusion_table(const ConfusionTable& confusion) {
  std::set<std::string> columns;
  for (const auto& [kind, row] : confusion) {
    for (const auto& [c, n] : row) columns.insert(c);
  }
  std::printf("%-18s", "gesture\\class");
  for (const auto& c : columns) std::printf(" %9.9s", c.c_str());
  std::printf("\n");
  for (const auto& [kind, row] : confusion) {
    std::printf("%-18s", kind.c_str());
    for (const auto& c : columns) {
      const auto it = row.find(c);
      std::printf(" %9d", it == row.end() ? 0 : it->second);
    }
    std::printf("\n");
  }
}

// The strokes: the shared corpus's $1 logs (subjects s01..s06) when present, else the generated
// corpus (gen::generated_dollar_dir(): subjects s01..s03, every speed, 5 of each of the 17
// single-stroke kinds; circle, rectangle and triangle are $1 names too).
inline bool full_dollar_corpus() { return shared_path("strokes/dollar1").has_value(); }
inline std::filesystem::path dollar_dir() {
  return full_dollar_corpus() ? *shared_path("strokes/dollar1") : gen::generated_dollar_dir();
}
inline std::size_t dollar_gesture_count() {
  return full_dollar_corpus() ? 2880U : 765U; // 6 x 3 x 16 x 10, or 3 x 3 x 17 x 5
}
// A count or rate that a test expects: `full` on the real s01..s06, `generated` on the generated
// corpus (figures measured on it, guarding against regressions; never used to tune the
// recognizer).
inline int dollar_count(int full, int generated) { return full_dollar_corpus() ? full : generated; }
inline double dollar_rate(double full, double generated) {
  return full_dollar_corpus() ? full : generated;
}

struct Gesture {
  std::string file;
  std::string name; // e.g. "triangle03"
  std::string kind; // the name without its digits
  std::vector<StrokePoint> points;
};

inline Gesture read_gesture(const std::filesystem::path& path) {
  dollar::Gesture read = dollar::read_dollar_xml(path);
  Gesture g;
  g.file = path.string();
  g.name = read.name;
  g.kind = read.kind();
  g.points = std::move(read.points);
  return g;
}

// Every $1 gesture under dollar_dir(), sorted by path.
inline std::vector<Gesture> all_dollar_gestures() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dollar_dir())) {
    if (e.is_regular_file() && e.path().extension() == ".xml") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<Gesture> out;
  out.reserve(files.size());
  for (const auto& f : files) out.push_back(read_gesture(f));
  return out;
}

// The stroke as a 1 kHz tablet would send it: one sample per millisecond from the first time
// stamp to the last, each linearly interpolated by time between the two logged samples around
// it, and the last logged sample at the end.
inline std::vector<StrokePoint> at_one_khz(const std::vector<StrokePoint>& in) {
  if (in.size() < 2) return in;
  std::vector<StrokePoint> out;
  std::size_t j = 0;
  for (std::size_t k = 0;; ++k) {
    const double t = in.front().t + 1e-3 * static_cast<double>(k);
    if (t > in.back().t) break;
    while (j + 2 < in.size() && in[j + 1].t < t) ++j;
    const StrokePoint& a = in[j];
    const StrokePoint& b = in[j + 1];
    double f = b.t > a.t ? (t - a.t) / (b.t - a.t) : 1.0;
    f = f < 0 ? 0 : (f > 1 ? 1 : f);
    out.push_back({a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), t});
  }
  out.push_back(in.back());
  return out;
}

// ---- Independent distance computations (brute force, no shared code with the recognizer) ----

inline double dist_point_segment(PointD p, PointD a, PointD b) {
  const double vx = b.x - a.x, vy = b.y - a.y;
  const double wx = p.x - a.x, wy = p.y - a.y;
  const double l2 = vx * vx + vy * vy;
  double t = l2 > 0 ? (wx * vx + wy * vy) / l2 : 0.0;
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  return std::hypot(wx - t * vx, wy - t * vy);
}

inline double dist_point_path(PointD p, const std::vector<PointD>& path) {
  if (path.size() == 1) return std::hypot(p.x - path[0].x, p.y - path[0].y);
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    best = std::min(best, dist_point_segment(p, path[i], path[i + 1]));
  }
  return best;
}

// Points along a path, at most `step` apart, ends included.
inline std::vector<PointD> densify(const std::vector<PointD>& path, double step) {
  std::vector<PointD> out;
  if (path.empty()) return out;
  out.push_back(path[0]);
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

// The clean shape as a fine polyline rebuilt from its parameters (circles, ellipses, arcs), or
// its vertex path (polygons close back to the first vertex).
inline std::vector<PointD> clean_path_from_params(const Recognition& r, std::size_t steps) {
  const ShapeParams& p = r.params;
  std::vector<PointD> out;
  auto ellipse_point = [&](double t, double a, double b) {
    const double c = std::cos(p.rotation), s = std::sin(p.rotation);
    const double x = a * std::cos(t), y = b * std::sin(t);
    return PointD{p.center.x + c * x - s * y, p.center.y + s * x + c * y};
  };
  switch (r.shape) {
    case ShapeClass::kCircle:
    case ShapeClass::kEllipse:
      for (std::size_t k = 0; k <= steps; ++k) {
        out.push_back(ellipse_point(
            2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(steps), p.radius_x,
            p.radius_y));
      }
      return out;
    case ShapeClass::kArc:
      for (std::size_t k = 0; k <= steps; ++k) {
        const double t =
            p.start_angle + p.sweep_angle * static_cast<double>(k) / static_cast<double>(steps);
        out.push_back(
            {p.center.x + p.radius_x * std::cos(t), p.center.y + p.radius_x * std::sin(t)});
      }
      return out;
    case ShapeClass::kSegment:
    case ShapeClass::kPolyline:
      return p.vertices;
    default:
      out = p.vertices;
      out.push_back(p.vertices.front());
      return out;
  }
}

// Independent estimate of the Hausdorff distance between the stroke's path and the snap's clean
// path: dense samples of each against the other path (brute force). For curves the clean path
// is a fine chord polygon rebuilt from the parameters; `chord_error` bounds how far its chords
// stray from the curve, so the estimate is within chord_error + step/2 of the true distance.
struct IndependentCheck {
  double hausdorff = 0.0;
  double slack = 0.0; // how far `hausdorff` may exceed the true distance
};

inline IndependentCheck independent_hausdorff(const std::vector<StrokePoint>& samples,
                                              const Recognition& r, double step) {
  std::vector<PointD> stroke;
  stroke.reserve(samples.size());
  for (const auto& s : samples) stroke.push_back({s.x, s.y});
  const std::size_t steps = 4096;
  const std::vector<PointD> clean = clean_path_from_params(r, steps);
  double chord_error = 0.0;
  if (r.shape == ShapeClass::kCircle || r.shape == ShapeClass::kEllipse ||
      r.shape == ShapeClass::kArc) {
    const double rmax = std::max(r.params.radius_x, r.params.radius_y);
    const double sweep =
        r.shape == ShapeClass::kArc ? std::abs(r.params.sweep_angle) : 2 * std::numbers::pi;
    const double chord = rmax * sweep / static_cast<double>(steps);
    chord_error = chord / 2; // a chord point is within half a chord of a curve point
  }
  IndependentCheck out;
  for (const PointD& p : densify(stroke, step)) {
    out.hausdorff = std::max(out.hausdorff, dist_point_path(p, clean));
  }
  for (const PointD& q : densify(clean, step)) {
    out.hausdorff = std::max(out.hausdorff, dist_point_path(q, stroke));
  }
  out.slack = chord_error;
  return out;
}

// Ink-level spot check: points of the clean ink (clean path + pen disk) and their distance to
// the stroke's ink, d(x, stroke ink) = max(0, d(x, stroke path) - r); and the other way round.
inline double ink_distance_lower_estimate(const std::vector<StrokePoint>& samples,
                                          const Recognition& r, double step) {
  std::vector<PointD> stroke_points;
  stroke_points.reserve(samples.size());
  for (const auto& s : samples) stroke_points.push_back({s.x, s.y});
  const std::vector<PointD>& stroke = stroke_points;
  const std::vector<PointD> clean = clean_path_from_params(r, 2048);
  const double pen = r.pen_radius;
  double worst = 0.0;
  for (const auto& [from, to] : {std::pair{&clean, &stroke}, std::pair{&stroke, &clean}}) {
    for (const PointD& q : densify(*from, step)) {
      for (int k = 0; k < 8; ++k) {
        const double a = k * std::numbers::pi / 4;
        const PointD x{q.x + pen * std::cos(a), q.y + pen * std::sin(a)};
        worst = std::max(worst, std::max(0.0, dist_point_path(x, *to) - pen));
      }
    }
  }
  return worst;
}

} // namespace penshape::test
