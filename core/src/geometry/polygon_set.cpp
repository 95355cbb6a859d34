// The public PolygonSet's functions (polygon_set.hpp): exact conversion, area, ring orientation.
#include "penshape/core/polygon_set.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/exact_double.hpp"
#include "geometry/ring_area.hpp"

namespace penshape {

std::size_t PolygonSet::vertex_count() const {
  std::size_t n = 0;
  for (const auto& p : polygons) {
    n += p.outer.size();
    for (const auto& h : p.holes) n += h.size();
  }
  return n;
}

Rational exact(double v) {
  // mpq_set_d is exact for finite doubles (they are dyadic rationals).
  Rational r;
  mpq_set_d(r.get_mpq_t(), v);
  return r;
}

ExactPoint exact(PointD p) { return {exact(p.x), exact(p.y)}; }

double to_double(const Rational& v) {
  bool is_double = false;
  const double d = detail::to_double_checked(v, is_double);
  if (is_double) return d; // grid coordinates: no rounding to decide
  // get_d truncates towards zero; step to the neighbour when that one is nearer.
  const double away = std::nextafter(d, sgn(v) < 0 ? -HUGE_VAL : HUGE_VAL);
  if (!std::isfinite(away)) return d;
  const Rational gap_d = abs(v - exact(d));
  const Rational gap_away = abs(v - exact(away));
  return gap_away < gap_d ? away : d;
}

PointD to_double(const ExactPoint& p) { return {to_double(p.x), to_double(p.y)}; }

Rational twice_signed_area(const Ring& ring) {
  return detail::twice_signed_area_in<Rational>(ring);
}

Rational area(const PolygonSet& set) {
  Rational twice = 0;
  for (const auto& p : set.polygons) {
    twice += abs(twice_signed_area(p.outer));
    for (const auto& h : p.holes) twice -= abs(twice_signed_area(h));
  }
  return twice / 2;
}

namespace {
// A rational's double without GMP's division when it is one exactly (relative error 2^-52 at
// most otherwise, as mpq_get_d's).
double fast_double(const Rational& v) {
  bool exact = false;
  return detail::to_double_checked(v, exact);
}
} // namespace

int orientation_sign(const Ring& ring) {
  // The shoelace sum in doubles decides unless it is within its rounding error (each term is
  // off by a few ulps of its magnitude); exact rationals decide the rest.
  double sum = 0;
  double magnitude = 0;
  const std::size_t n = ring.size();
  if (n == 0) return 0;
  // Each vertex converted once (the conversion is most of the cost on 200,000 vertices).
  const double x0 = fast_double(ring[0].x), y0 = fast_double(ring[0].y);
  double ax = x0, ay = y0;
  for (std::size_t i = 0; i < n; ++i) {
    const bool last = i + 1 == n;
    const double bx = last ? x0 : fast_double(ring[i + 1].x);
    const double by = last ? y0 : fast_double(ring[i + 1].y);
    const double t1 = ax * by;
    const double t2 = ay * bx;
    sum += t1 - t2;
    magnitude += std::abs(t1) + std::abs(t2);
    ax = bx;
    ay = by;
  }
  if (std::isfinite(sum) && std::isfinite(magnitude) && magnitude > 1e-250 &&
      std::abs(sum) > 1e-12 * magnitude * static_cast<double>(n)) {
    return sum > 0 ? 1 : -1;
  }
  return sgn(twice_signed_area(ring));
}

bool has_normalized_orientation(const PolygonSet& set) {
  for (const auto& p : set.polygons) {
    if (orientation_sign(p.outer) < 0) return false;
    for (const auto& h : p.holes) {
      if (orientation_sign(h) > 0) return false;
    }
  }
  return true;
}

void normalize_orientation(PolygonSet& set) {
  for (auto& p : set.polygons) {
    if (orientation_sign(p.outer) < 0) std::reverse(p.outer.begin(), p.outer.end());
    for (auto& h : p.holes) {
      if (orientation_sign(h) > 0) std::reverse(h.begin(), h.end());
    }
  }
}

} // namespace penshape
