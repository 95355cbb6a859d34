#pragma once
// The foot parameter of a point on an ellipse, shared by the clean shape's distance and the
// certified distance (which only takes it as a proposal).

namespace penshape::recognize_detail {

// For a point (x, y) >= 0 in the frame of the ellipse (a cos t, b sin t): t in [0, pi/2] from
// Newton on the foot-point condition g(t) = (a^2 - b^2) sin t cos t - a x sin t + b y cos t = 0.
// Whatever t it ends with, (a cos t, b sin t) lies on the ellipse, so the distance to it is an
// upper bound (exact when converged).
double ellipse_foot_parameter(double x, double y, double a, double b);

} // namespace penshape::recognize_detail
