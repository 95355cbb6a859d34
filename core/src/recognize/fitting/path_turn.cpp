// Turns of a drawn path near a shape's corners (path_turn.hpp).
#include "recognize/fitting/path_turn.hpp"

#include <algorithm>
#include <cmath>

namespace penshape::recognize_detail {

ArcLengthPath::ArcLengthPath(const std::vector<PointD>& path) : path_(path), lengths_{0.0} {
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    lengths_.push_back(lengths_.back() + distance(path[i], path[i + 1]));
  }
}

PointD ArcLengthPath::point_at(double at) const {
  const auto it = std::lower_bound(lengths_.begin(), lengths_.end(), at);
  if (it == lengths_.begin()) return path_.front();
  if (it == lengths_.end()) return path_.back();
  const auto k = static_cast<std::size_t>(it - lengths_.begin());
  const double span = lengths_[k] - lengths_[k - 1];
  const double w = span > 0.0 ? (at - lengths_[k - 1]) / span : 0.0;
  return path_[k - 1] + w * (path_[k] - path_[k - 1]);
}

ArcLengthPath::Nearest ArcLengthPath::nearest(PointD v) const {
  if (path_.size() == 1) return {0.0, distance(v, path_[0])};
  Nearest out{0.0, INFINITY}; // distance squared until the end
  for (std::size_t i = 0; i + 1 < path_.size(); ++i) {
    const PointD d = path_[i + 1] - path_[i];
    const double len2 = dot(d, d);
    const double w = len2 > 0.0 ? std::clamp(dot(v - path_[i], d) / len2, 0.0, 1.0) : 0.0;
    const PointD off = v - (path_[i] + w * d);
    const double dist2 = dot(off, off);
    if (dist2 < out.distance) out = {lengths_[i] + w * (lengths_[i + 1] - lengths_[i]), dist2};
  }
  out.distance = std::sqrt(out.distance);
  return out;
}

std::optional<double> ArcLengthPath::turn_at(double at, double half_width) const {
  if (at - half_width < 0.0 || at + half_width > length()) return std::nullopt;
  const PointD p = point_at(at);
  return angle_between(p - point_at(at - half_width), point_at(at + half_width) - p);
}

} // namespace penshape::recognize_detail
