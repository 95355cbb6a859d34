// Dots (dot.hpp): one position, recognized as itself.
#include "recognize/fitting/dot.hpp"

namespace penshape::recognize_detail {

bool is_dot(const std::vector<StrokePoint>& samples) {
  if (samples.empty()) return false;
  for (const StrokePoint& s : samples) {
    if (s.x != samples.front().x || s.y != samples.front().y) return false;
  }
  return true;
}

Recognition dot_recognition(const std::vector<StrokePoint>& samples, const ToleranceChoice& tol) {
  const PointD p{samples.front().x, samples.front().y};
  Recognition out;
  out.shape = ShapeClass::kDot;
  out.params.vertices = {p};
  out.params.center = p;
  out.clean = {p};
  out.epsilon = tol.epsilon;
  out.pen_radius = tol.pen_radius;
  // The stroke's path and the clean path are the same point: the bound 0 is exact.
  out.certificate.certified = true;
  out.certificate.bound = 0.0;
  out.certificate.epsilon = tol.epsilon;
  out.certificate.pen_radius = tol.pen_radius;
  out.confidence = 1.0;
  return out;
}

} // namespace penshape::recognize_detail
