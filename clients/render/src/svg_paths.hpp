#pragma once
// Internal: SVG path data for regions swept by a disk (true arcs), in screen coordinates
// (x right, y down; SVG's sweep-flag 1 turns from +x towards +y).
#include <initializer_list>
#include <string>
#include <vector>

#include "penshape/core/polygon_set.hpp"

namespace penshape::render::detail {

// A number for SVG: short, fixed notation, never "nan".
std::string num(double v);

class PathBuilder {
 public:
  void move_to(PointD p);
  void line_to(PointD p);
  // Arc around `center` from the current point to `to` (same radius), turning by less than pi
  // when `large` is false, in SVG's positive direction when `positive` is true.
  void arc_to(PointD to, double radius, bool large, bool positive);
  void close();
  void circle(PointD center, double radius, bool positive); // a full circle as two half arcs
  [[nodiscard]] const std::string& str() const { return d_; }
  [[nodiscard]] bool empty() const { return d_.empty(); }

 private:
  void command(char c, std::initializer_list<double> values);
  std::string d_;
};

// The stadium {x : dist(x, [a, b]) <= radius} as one closed path (a disk when a == b).
void capsule(PathBuilder& path, PointD a, PointD b, double radius);

// A closed polygonal ring.
void ring(PathBuilder& path, const std::vector<PointD>& points);

// The band {x : | dist(x, center) - radius | <= width} restricted to the arc from `start` turning
// by `sweep` (screen angles, radians), with round caps: an arc drawn with a pen of radius `width`.
void arc_band(PathBuilder& path, PointD center, double radius, double start, double sweep,
              double width);

// The arc itself as an open path.
void arc_line(PathBuilder& path, PointD center, double radius, double start, double sweep);

} // namespace penshape::render::detail
