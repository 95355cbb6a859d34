#include "intervals.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace penshape::annulus::detail {

void clip_linear(double& lo, double& hi, double alpha, double beta, bool strict) {
  if (lo > hi) return;
  if (beta == 0.0) {
    if (alpha > 0.0 || (strict && alpha == 0.0)) hi = lo - 1.0;
    return;
  }
  const double root = -alpha / beta;
  if (beta > 0.0) {
    hi = std::min(hi, root);
  } else {
    lo = std::max(lo, root);
  }
}

bool quadratic_leq(double a, double b, double c, double& lo, double& hi) {
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0 || lo > hi) return false;
  const double sq = std::sqrt(disc);
  // Numerically stable roots.
  const double qv = -0.5 * (b + std::copysign(sq, b));
  double r1 = qv / a;
  double r2 = qv != 0.0 ? c / qv : r1;
  if (r1 > r2) std::swap(r1, r2);
  lo = std::max(lo, r1);
  hi = std::min(hi, r2);
  return lo <= hi;
}

void trig_leq(double A, double B, double C, double lo, double hi, IntervalSet& out) {
  if (lo > hi) return;
  const double r = std::sqrt(A * A + B * B); // coordinates are bounded (Limits): no overflow
  if (r == 0.0 || C >= r) {
    if (r == 0.0 && C < 0.0) return;
    out.push_back({lo, hi});
    return;
  }
  if (C <= -r) return;
  // A cos + B sin = r cos(phi - psi) <= C  <=>  phi - psi in [alpha, 2 pi - alpha] (mod 2 pi).
  const double psi = std::atan2(B, A);
  const double alpha = std::acos(C / r);
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double start = psi + alpha;
  const double len = kTwoPi - 2.0 * alpha;
  // Shift the periodic interval family so it starts at or before lo.
  start -= kTwoPi * std::ceil((start - lo) / kTwoPi);
  const std::size_t first = out.size();
  for (double s = start; s <= hi; s += kTwoPi) {
    const double a = std::max(lo, s);
    const double b = std::min(hi, s + len);
    if (a <= b) out.push_back({a, b});
  }
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
            [](const Interval& x, const Interval& y) { return x.lo < y.lo; });
}

void normalize(IntervalSet& s) {
  if (s.size() < 2) return;
  std::sort(s.begin(), s.end(), [](const Interval& x, const Interval& y) { return x.lo < y.lo; });
  std::size_t w = 0;
  for (std::size_t i = 1; i < s.size(); ++i) {
    if (s[i].lo <= s[w].hi) {
      s[w].hi = std::max(s[w].hi, s[i].hi);
    } else {
      s[++w] = s[i];
    }
  }
  s.resize(w + 1);
}

IntervalSet intersect(const IntervalSet& a, const IntervalSet& b) {
  IntervalSet out;
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() && j < b.size()) {
    const double lo = std::max(a[i].lo, b[j].lo);
    const double hi = std::min(a[i].hi, b[j].hi);
    if (lo <= hi) out.push_back({lo, hi});
    if (a[i].hi < b[j].hi) {
      ++i;
    } else {
      ++j;
    }
  }
  return out;
}

IntervalSet subtract_interior(const IntervalSet& a, const IntervalSet& b) {
  IntervalSet out;
  std::size_t j = 0;
  for (const Interval& iv : a) {
    double lo = iv.lo;
    bool alive = true;
    while (j < b.size() && b[j].hi <= lo) ++j;
    for (std::size_t k = j; k < b.size() && b[k].lo < iv.hi; ++k) {
      // b[k] = (bl, bh) open removes points strictly inside.
      if (b[k].lo > lo) out.push_back({lo, b[k].lo});
      lo = std::max(lo, b[k].hi);
      if (lo > iv.hi) {
        alive = false;
        break;
      }
    }
    if (alive && lo <= iv.hi) out.push_back({lo, iv.hi});
  }
  normalize(out);
  return out;
}

} // namespace penshape::annulus::detail
