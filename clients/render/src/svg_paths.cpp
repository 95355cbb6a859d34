#include "svg_paths.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace penshape::render::detail {

std::string num(double v) {
  if (!std::isfinite(v)) return "0";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  // Trim trailing zeros: "12.5000" -> "12.5", "3.0000" -> "3".
  std::string s(buf);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

// Appending piece by piece: g++ 12 at -O3 warns falsely (-Wrestrict) on "literal" + string.
void PathBuilder::command(char c, std::initializer_list<double> values) {
  d_ += c;
  bool first = true;
  for (const double v : values) {
    if (!first) d_ += ' ';
    first = false;
    d_ += num(v);
  }
}

void PathBuilder::move_to(PointD p) { command('M', {p.x, p.y}); }
void PathBuilder::line_to(PointD p) { command('L', {p.x, p.y}); }
void PathBuilder::arc_to(PointD to, double radius, bool large, bool positive) {
  command('A', {radius, radius, 0.0, large ? 1.0 : 0.0, positive ? 1.0 : 0.0, to.x, to.y});
}
void PathBuilder::close() { d_ += "Z"; }

void PathBuilder::circle(PointD c, double radius, bool positive) {
  move_to({c.x + radius, c.y});
  arc_to({c.x - radius, c.y}, radius, false, positive);
  arc_to({c.x + radius, c.y}, radius, false, positive);
  close();
}

void capsule(PathBuilder& path, PointD a, PointD b, double radius) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double len = std::hypot(dx, dy);
  if (len == 0.0) {
    path.circle(a, radius, true);
    return;
  }
  // u along the segment, n = u turned by +90 degrees in screen coordinates.
  const PointD u{dx / len * radius, dy / len * radius};
  const PointD n{-u.y, u.x};
  // Around the outline in SVG's negative direction: b's cap goes from b-n through b+u to b+n.
  path.move_to({a.x - n.x, a.y - n.y});
  path.line_to({b.x - n.x, b.y - n.y});
  path.arc_to({b.x + u.x, b.y + u.y}, radius, false, true);
  path.arc_to({b.x + n.x, b.y + n.y}, radius, false, true);
  path.line_to({a.x + n.x, a.y + n.y});
  path.arc_to({a.x - u.x, a.y - u.y}, radius, false, true);
  path.arc_to({a.x - n.x, a.y - n.y}, radius, false, true);
  path.close();
}

void ring(PathBuilder& path, const std::vector<PointD>& points) {
  if (points.empty()) return;
  path.move_to(points.front());
  for (std::size_t i = 1; i < points.size(); ++i) path.line_to(points[i]);
  path.close();
}

namespace {

PointD polar(PointD c, double r, double angle) {
  return {c.x + r * std::cos(angle), c.y + r * std::sin(angle)};
}

} // namespace

void arc_line(PathBuilder& path, PointD center, double radius, double start, double sweep) {
  path.move_to(polar(center, radius, start));
  path.arc_to(polar(center, radius, start + sweep), radius, std::abs(sweep) > std::numbers::pi,
              sweep > 0);
}

void arc_band(PathBuilder& path, PointD center, double radius, double start, double sweep,
              double width) {
  const double end = start + sweep;
  const bool large = std::abs(sweep) > std::numbers::pi;
  const bool forward = sweep > 0;
  const double outer = radius + width;
  const double inner = radius - width;
  if (inner <= 0) {
    // The pen covers the center: the sector of radius outer, plus the two end disks.
    path.move_to(center);
    path.line_to(polar(center, outer, start));
    path.arc_to(polar(center, outer, end), outer, large, forward);
    path.close();
    path.circle(polar(center, radius, start), width, forward);
    path.circle(polar(center, radius, end), width, forward);
    return;
  }
  path.move_to(polar(center, outer, start));
  path.arc_to(polar(center, outer, end), outer, large, forward);
  // Round caps: half circles of radius `width` around the end points, away from the arc.
  path.arc_to(polar(center, inner, end), width, false, forward);
  path.arc_to(polar(center, inner, start), inner, large, !forward);
  path.arc_to(polar(center, outer, start), width, false, forward);
  path.close();
}

} // namespace penshape::render::detail
