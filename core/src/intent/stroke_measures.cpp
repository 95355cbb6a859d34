// One stroke's measures for the writing/drawing decision (stroke_measures.hpp).
#include "stroke_measures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "penshape/core/deconstruct.hpp"

namespace penshape::intent {
namespace {

struct P {
  double x, y;
};

// The path thinned to steps of at least `step` mm, so that sensor jitter does not count as
// turning; the last point is kept.
std::vector<P> thinned(const std::vector<P>& pts, double step) {
  std::vector<P> out{pts.front()};
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const bool last = i + 1 == pts.size();
    if (std::hypot(pts[i].x - out.back().x, pts[i].y - out.back().y) >= step) {
      out.push_back(pts[i]);
    } else if (last && out.size() > 1) {
      out.back() = pts[i];
    }
  }
  return out;
}

// Total absolute turning and the changes of its sign (turns under 0.15 rad are not counted as a
// direction, so that a straight run's noise makes no reversals).
void add_turning(const std::vector<P>& path, StrokeMeasures& m) {
  int last_sign = 0;
  for (std::size_t i = 2; i < path.size(); ++i) {
    const double a0 = std::atan2(path[i - 1].y - path[i - 2].y, path[i - 1].x - path[i - 2].x);
    const double a1 = std::atan2(path[i].y - path[i - 1].y, path[i].x - path[i - 1].x);
    double turn = a1 - a0;
    if (turn > std::numbers::pi) turn -= 2 * std::numbers::pi;
    if (turn < -std::numbers::pi) turn += 2 * std::numbers::pi;
    m.turning += std::abs(turn);
    if (std::abs(turn) < 0.15) continue;
    const int sign = turn > 0 ? 1 : -1;
    if (last_sign != 0 && sign != last_sign) ++m.reversals;
    last_sign = sign;
  }
}

void add_timing(IntentStroke stroke, StrokeMeasures& m) {
  m.start_t = stroke.front().t;
  m.end_t = stroke.back().t;
  bool increasing = m.end_t > m.start_t;
  for (std::size_t i = 1; i < stroke.size() && increasing; ++i) {
    increasing = stroke[i].t >= stroke[i - 1].t;
  }
  m.timed = increasing;
  if (m.timed) m.speed = m.length / (m.end_t - m.start_t);
}

} // namespace

StrokeMeasures measure_stroke(IntentStroke stroke, double mm_per_unit) {
  StrokeMeasures m;
  std::vector<P> pts;
  pts.reserve(stroke.size());
  for (std::size_t i = 0; i < stroke.size(); ++i) {
    const StrokePoint& s = stroke[i];
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.t)) {
      throw InvalidInput("intent: sample " + std::to_string(i) + " is not finite");
    }
    const P p{s.x * mm_per_unit, s.y * mm_per_unit};
    m.box = {std::min(m.box.x0, p.x), std::min(m.box.y0, p.y), std::max(m.box.x1, p.x),
             std::max(m.box.y1, p.y)};
    if (!pts.empty()) m.length += std::hypot(p.x - pts.back().x, p.y - pts.back().y);
    pts.push_back(p);
  }
  if (pts.empty()) {
    m.box = {0, 0, 0, 0};
    return m;
  }
  m.size = std::max(m.box.width(), m.box.height());
  m.dot = !(m.size > 0);
  add_timing(stroke, m);
  if (m.dot) return m;
  const double chord = std::hypot(pts.back().x - pts.front().x, pts.back().y - pts.front().y);
  m.straightness = chord / m.length;
  m.closedness = chord / m.size;
  add_turning(thinned(pts, std::max(0.3, 0.02 * m.size)), m);
  return m;
}

} // namespace penshape::intent
