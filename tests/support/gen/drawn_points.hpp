#pragma once
// The first stroke of a generated drawing as plain points, the form the geometry tests use for
// the real $1 strokes (tests/core/support/dollar1.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "penshape/core/polygon_set.hpp"
#include "stroke_gen.hpp"

namespace penshape::gen {

inline std::vector<PointD> drawn_points(std::uint64_t seed, const std::string& kind) {
  StrokeGenerator generator(seed);
  std::vector<PointD> out;
  const Drawing drawing = generator.draw(kind); // kept: a range-for would not extend its life
  for (const auto& p : drawing.strokes.front().points) out.push_back({p.x, p.y});
  return out;
}

} // namespace penshape::gen
