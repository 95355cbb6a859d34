#pragma once
// A rectangle drawn side by side as a hand would (the grouping tests' input), and small helpers
// to read the answers about it.
#include <google/protobuf/repeated_field.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "penshape/core/polygon_set.hpp"
#include "penshape/v1/shape.pb.h"

namespace penshape::daemon_test {

// A hand-drawn straight side from a to b (mm): 40 samples with a small wobble across it.
inline std::vector<PointD> side(PointD a, PointD b) {
  std::vector<PointD> out;
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  const PointD n{-(b.y - a.y) / len, (b.x - a.x) / len};
  for (int i = 0; i <= 40; ++i) {
    const double f = i / 40.0;
    const double w = 0.25 * std::sin(9.0 * f);
    out.push_back({a.x + f * (b.x - a.x) + w * n.x, a.y + f * (b.y - a.y) + w * n.y});
  }
  return out;
}

// The four sides of the rectangle (x0, y0)-(x1, y1), with a small gap or overshoot at corners.
inline std::vector<std::vector<PointD>> rectangle_sides(double x0, double y0, double x1,
                                                        double y1) {
  return {side({x0 - 0.3, y0}, {x1 + 0.4, y0 + 0.2}), side({x1, y0 + 0.5}, {x1 + 0.2, y1 - 0.3}),
          side({x1 + 0.3, y1}, {x0 - 0.2, y1 + 0.2}), side({x0, y1 + 0.4}, {x0 + 0.2, y0 + 0.3})};
}

inline bool is_rectangle(v1::ShapeKind k) {
  return k == v1::SHAPE_KIND_RECTANGLE || k == v1::SHAPE_KIND_SQUARE ||
         k == v1::SHAPE_KIND_QUADRILATERAL;
}

inline std::vector<std::uint64_t> ids_of(const google::protobuf::RepeatedField<std::uint64_t>& f) {
  return {f.begin(), f.end()};
}

} // namespace penshape::daemon_test
