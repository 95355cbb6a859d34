// An arrow's tip is an end (arrow_tip.hpp).
#include "recognize/group/arrow_tip.hpp"

#include <cmath>

#include "recognize/arrow/arrow_limits.hpp"
#include "recognize/group/group_plausibility.hpp"

namespace penshape::recognize_detail {
namespace {

// Whether `path`, walked from index `from` by `step` (+1 or -1), leaves the disk of radius
// `join` around `tip` and reaches 2 `join` from it inside the cone around `forward`.
bool leaves_forward(const std::vector<PointD>& path, std::size_t from, int step, PointD tip,
                    PointD forward, double join) {
  const double max_angle = group_rules().max_continuation_angle;
  for (auto i = static_cast<std::ptrdiff_t>(from);
       i >= 0 && i < static_cast<std::ptrdiff_t>(path.size()); i += step) {
    const PointD d = path[static_cast<std::size_t>(i)] - tip;
    const double r = norm(d);
    if (r <= join) continue; // still at the tip
    if (angle_between(forward, d) > max_angle) return false;
    if (r >= 2.0 * join) return true;
  }
  return false;
}

// Whether some path leaves `tip` forward (along `forward`).
bool continued_at(PointD tip, PointD forward, std::span<const std::vector<PointD>> others,
                  double join) {
  if (norm(forward) <= 0.0) return false;
  for (const std::vector<PointD>& p : others) {
    std::size_t nearest = 0;
    double best = INFINITY;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double d = distance(p[i], tip);
      if (d < best) best = d, nearest = i;
    }
    if (best > join) continue;
    if (leaves_forward(p, nearest, 1, tip, forward, join) ||
        leaves_forward(p, nearest, -1, tip, forward, join)) {
      return true;
    }
  }
  return false;
}

} // namespace

std::string tip_continued(const Recognition& r, std::span<const std::vector<PointD>> others,
                          double join) {
  const bool single = r.shape == ShapeClass::kArrow;
  if (!group_rules().no_continued_tips || (!single && r.shape != ShapeClass::kDoubleArrow)) {
    return {};
  }
  const std::vector<PointD>& v = r.params.vertices;
  if (v.size() < (single ? 4u : 6u)) return {};
  const double bulge = r.params.shaft_bulge;
  const std::vector<PointD>& bends = r.params.shaft_bends;
  // Forward at the tip is away from the shaft; at a double arrow's tail, away from it too.
  const PointD ahead = -1.0 * shaft_back(v[0], v[1], bulge, bends);
  if (continued_at(v[1], ahead, others, join) ||
      (!single &&
       continued_at(v[0], -1.0 * shaft_forward(v[0], v[1], bulge, bends), others, join))) {
    return "a stroke leaves the arrow's tip forward (the tip is no end: a figure, no arrow)";
  }
  return {};
}

} // namespace penshape::recognize_detail
