#pragma once
// Certified upper bounds for the path certificates (certificate.cpp, union_certificate.cpp):
// doubles propose (the nearest segment, the foot point on a curve) and the bound is evaluated in
// interval arithmetic with directed rounding through geometry/distance_kernel.hpp. A proposal
// that is not the nearest only loosens a bound, so no tolerance decides a certificate. These
// functions hold their own rounding guards: call them in the default rounding mode (they call
// sin and cos, whose accuracy the C library states for it).
//
// A shape of several pieces (CleanShape::jumps, an arrow whose shaft stops short of its tip) is
// the set B = B_1 u ... u B_k of its pieces; the step from one piece to the next is no part of
// it. Both one-sided terms of the Hausdorff bound hold as for one polyline:
//   - to the shape: d(x, B) = min_i d(x, B_i) <= d(x, s) for every segment s of every piece, so
//     the interval distance to the one segment a double proposes bounds d(x, B) for every x of a
//     box (a jump is never proposed: its points are not in B, so its distance bounds nothing);
//   - from the shape: sup_{b in B} d(b, A) = max_i sup_{b in B_i} d(b, A), and farthest_from
//     samples every segment of every piece (never a jump), each point within half a step of a
//     sample, keeping the greatest bound.
// The ink certificate (ink_certificate.cpp) reads the pieces the same way: its upper bound is
// the least over the pieces' segments, and its "maybe within rho" test looks at those only.
#include <cstdint>
#include <functional>
#include <span>

#include "geometry/distance_kernel.hpp"
#include "recognize/fitting/clean_shape.hpp"
#include "recognize/fitting/geometry.hpp"

namespace penshape::recognize_detail {

// A clean shape with its constants enclosed once (rotation's cos and sin, the curve's end).
class CertifiedShape {
 public:
  explicit CertifiedShape(const CleanShape& shape);

  // >= d(x, shape) for every x in `box`; `near` (a double point of the box) proposes the foot.
  [[nodiscard]] double upper(const detail::IPoint& box, PointD near) const;

  // >= sup over the shape of the distance to the segments `index` holds (every point of the shape
  // within half a sampling step of a sample, added), sampling steps about h.
  [[nodiscard]] double farthest_from(const SegmentIndex& index, double h) const;
  // The same with the proposal from `nearest(q, floor)`: a segment of the other side, the nearest
  // to q or one within floor of it.
  [[nodiscard]] double farthest_from(const std::function<Segment(PointD, double)>& nearest,
                                     double h) const;

  // >= the distance from the true shape to the one the parameters above sample, for curves:
  // the speed times the rounding of the curve's end parameter t0 + sweep (0 for polylines).
  [[nodiscard]] double end_slack() const { return end_slack_; }

  [[nodiscard]] const CleanShape& shape() const { return shape_; }

  // Encloses shape.at(t) (curves only).
  [[nodiscard]] detail::IPoint curve_point(double t) const;

 private:
  const CleanShape& shape_;
  detail::IntervalNT cos_r_{1.0}, sin_r_{0.0};
  double end_slack_ = 0.0;
};

// >= sup over the segment [a, b] of d(., shape), sampled with n = ceil(|b - a| / h) pieces
// (half a piece added). `a == b` allowed.
double segment_to_shape(PointD a, PointD b, double h, const CertifiedShape& shape);

// >= the distance from every point of `box` to the segment `s`.
double upper_to_segment(const detail::IPoint& box, const Segment& s);

// The point a + (k / n)(b - a) enclosed, and half the piece length |b - a| / (2 n) rounded up.
detail::IPoint point_on(PointD a, PointD b, std::size_t k, std::size_t n);
double half_piece(PointD a, PointD b, std::size_t n);

// (x + y + ...) rounded up.
double sum_up(std::initializer_list<double> terms);

} // namespace penshape::recognize_detail
