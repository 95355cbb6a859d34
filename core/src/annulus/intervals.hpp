#pragma once
// Closed parameter intervals (along a boundary piece, or of the rotation angle) and the two
// primitives every containing set reduces to: a linear constraint on a segment parameter and a
// sine constraint A cos(phi) + B sin(phi) <= C on an angle range. Doubles; callers widen the
// annulus by a margin where a NO must be robust.
#include <vector>

namespace penshape::annulus::detail {

struct Interval {
  double lo;
  double hi;
};

// Sorted by lo, pairwise disjoint, lo <= hi.
using IntervalSet = std::vector<Interval>;

// Keeps u in [lo, hi] with alpha + beta * u <= 0 (lo > hi afterwards means empty). With
// `strict`, a constraint that does not depend on u (beta == 0) must hold strictly: a segment
// lying on the boundary of an open set is outside it.
void clip_linear(double& lo, double& hi, double alpha, double beta, bool strict = false);

// {u in [lo, hi] : a u^2 + b u + c <= 0} for a > 0: one interval or none (returns false).
bool quadratic_leq(double a, double b, double c, double& lo, double& hi);

// {phi in [lo, hi] : A cos phi + B sin phi <= C}, hi - lo <= 2 pi + tiny. Appends to `out`
// (sorted, disjoint).
void trig_leq(double A, double B, double C, double lo, double hi, IntervalSet& out);

// Sorts and merges overlapping or touching intervals.
void normalize(IntervalSet& s);

IntervalSet intersect(const IntervalSet& a, const IntervalSet& b);

// a minus the interior of b (b's endpoints stay in the result: the annulus is closed).
IntervalSet subtract_interior(const IntervalSet& a, const IntervalSet& b);

} // namespace penshape::annulus::detail
