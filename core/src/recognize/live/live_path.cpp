// The live recognizer's path (see live_path.hpp).
#include "recognize/live/live_path.hpp"

#include <algorithm>
#include <cmath>

namespace penshape::recognize_detail {

bool LivePath::add(PointD p) {
  kept_grew_ = false;
  if (!points_.empty() && points_.back() == p) return false;
  if (points_.empty()) lo_ = hi_ = p;
  lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y)};
  hi_ = {std::max(hi_.x, p.x), std::max(hi_.y, p.y)};
  points_.push_back(p);
  if (kept_.empty() || distance(kept_.back(), p) >= thin_fraction_ * size()) {
    kept_.push_back(p);
    kept_grew_ = true;
  }
  return true;
}

double LivePath::magnitude() const {
  return std::max({std::abs(lo_.x), std::abs(lo_.y), std::abs(hi_.x), std::abs(hi_.y)});
}

ToleranceChoice LivePath::tolerance(const RecognizerConfig& config) const {
  // The rule depends on the samples only through their bounding box: its two corners give it.
  return choose_tolerance({StrokePoint{lo_.x, lo_.y, 0.0}, StrokePoint{hi_.x, hi_.y, 0.0}}, config);
}

std::vector<PointD> LivePath::fit_path(std::size_t cap) const {
  std::vector<PointD> path = kept_;
  if (!points_.empty() && !(path.back() == points_.back())) path.push_back(points_.back());
  cap = std::max<std::size_t>(cap, 2);
  if (path.size() <= cap) return path;
  std::vector<PointD> out;
  out.reserve(cap);
  const double stride = static_cast<double>(path.size() - 1) / static_cast<double>(cap - 1);
  for (std::size_t k = 0; k < cap; ++k) {
    const auto i = static_cast<std::size_t>(std::lround(stride * static_cast<double>(k)));
    const PointD q = path[std::min(i, path.size() - 1)];
    if (out.empty() || !(out.back() == q)) out.push_back(q);
  }
  return out;
}

} // namespace penshape::recognize_detail
