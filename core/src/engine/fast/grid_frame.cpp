#include "grid_frame.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <utility>

#include <CGAL/gmpxx.h>

#include "geometry/exact_double.hpp"

namespace penshape::fast {
namespace {

constexpr int kUnitsPerDeltaLog2 = 10; // about 2^10 grid units per delta
constexpr int kMinUnitsPerDeltaLog2 = 6;

Rational pow2(int k) {
  Rational v = 1;
  if (k >= 0) {
    mpq_mul_2exp(v.get_mpq_t(), v.get_mpq_t(), static_cast<mp_bitcnt_t>(k));
  } else {
    mpq_div_2exp(v.get_mpq_t(), v.get_mpq_t(), static_cast<mp_bitcnt_t>(-k));
  }
  return v;
}

// floor(v) for a rational.
mpz_class floor_q(const Rational& v) {
  mpz_class f;
  mpz_fdiv_q(f.get_mpz_t(), v.get_num_mpz_t(), v.get_den_mpz_t());
  return f;
}

// One side of the box: the exact extreme coordinate seen so far and its double. Doubles decide
// unless they tie: to_double_checked is v truncated towards zero in every case, a monotone map,
// so d(v) < d(w) proves v < w; only equal doubles ask the rationals. The extreme found is the
// one the rational comparisons alone would find (a GMP comparison per coordinate was 7% of KAZ's
// decision).
struct Extreme {
  const Rational* v = nullptr;
  double d = 0.0;
};

// sign -1 keeps the least value, +1 the greatest.
void keep_extreme(Extreme& e, const Rational& v, double d, int sign) {
  if (e.v == nullptr) {
    e = {&v, d};
    return;
  }
  const bool beyond =
      sign < 0 ? (d < e.d || (d == e.d && v < *e.v)) : (d > e.d || (d == e.d && v > *e.v));
  if (beyond) e = {&v, d};
}

} // namespace

GridFrame::GridFrame(const PolygonSet& q, const DeconstructParams& params) {
  Extreme lo_x, lo_y, hi_x, hi_y;
  for (const auto& poly : q.polygons) {
    for (const auto& p : poly.outer) {
      bool exact = false;
      const double x = detail::to_double_checked(p.x, exact);
      const double y = detail::to_double_checked(p.y, exact);
      keep_extreme(lo_x, p.x, x, -1);
      keep_extreme(lo_y, p.y, y, -1);
      keep_extreme(hi_x, p.x, x, 1);
      keep_extreme(hi_y, p.y, y, 1);
    }
  }
  const Rational zero;
  const Rational& min_x = lo_x.v != nullptr ? *lo_x.v : zero;
  const Rational& min_y = lo_y.v != nullptr ? *lo_y.v : zero;
  const Rational& max_x = hi_x.v != nullptr ? *hi_x.v : zero;
  const Rational& max_y = hi_y.v != nullptr ? *hi_y.v : zero;
  // Holes lie inside their outer ring, so the outers' box is the box of q.
  const Rational extent = std::max(max_x - min_x, max_y - min_y) +
                          2 * (params.radius + params.tolerance + 2 * params.precision);
  int exponent = 0;
  std::frexp(params.precision.get_d(), &exponent); // delta in [2^(e-1), 2^e)
  k_ = kUnitsPerDeltaLog2 - (exponent - 1);
  while (k_ > (kMinUnitsPerDeltaLog2 - (exponent - 1)) &&
         Rational(extent * pow2(k_)).get_d() > kMaxGridCoordinate) {
    --k_;
  }
  if (Rational(extent * pow2(k_)).get_d() > kMaxGridCoordinate) {
    throw InvalidInput("fast engine: the coordinate extent (" + std::to_string(extent.get_d()) +
                       " including r + eps margins) exceeds 2^24 times the precision delta (" +
                       std::to_string(params.precision.get_d()) +
                       "); use a coarser precision or the reference engine");
  }
  // Translate so the box corner (less the offset margin) is near the origin.
  const Rational margin = params.radius + params.tolerance + 2 * params.precision;
  tx_ = floor_q((min_x - margin) * pow2(k_));
  ty_ = floor_q((min_y - margin) * pow2(k_));
}

double GridFrame::units(const Rational& length) const {
  return Rational(length * pow2(k_)).get_d();
}

Bounds GridFrame::bounds(const Rational& length) const {
  const std::pair<double, double> iv = CGAL::to_interval(Rational(length * pow2(k_)));
  return {iv.first, iv.second};
}

namespace {

// round(v · 2^k) - t = floor((2 · num · 2^k + den) / (2 · den)) - t with integer operations only
// (a rational product would pay for a gcd per coordinate).
std::int64_t round_scaled(const Rational& v, int k, const mpz_class& t, mpz_class& num,
                          mpz_class& den) {
  // Fast path in 128-bit integers when everything fits (numerator and denominator below 2^62,
  // shifts below 60 bits, translation in 64 bits): the same formula, exactly.
  if (v.get_num().fits_slong_p() && v.get_den().fits_slong_p() && t.fits_slong_p() && k < 60 &&
      k > -60) {
    Int128 n = static_cast<Int128>(v.get_num().get_si());
    Int128 d = static_cast<Int128>(v.get_den().get_si());
    if (n > -(Int128(1) << 62) && n < (Int128(1) << 62) && d < (Int128(1) << 62)) {
      if (k >= 0) {
        n <<= (k + 1);
      } else {
        d <<= -k;
        n <<= 1;
      }
      n += d;
      d *= 2;
      Int128 q = n / d;
      if (n % d != 0 && n < 0) --q; // floor for negative quotients
      return static_cast<std::int64_t>(q - static_cast<Int128>(t.get_si()));
    }
  }
  num = v.get_num();
  den = v.get_den();
  if (k >= 0) {
    mpz_mul_2exp(num.get_mpz_t(), num.get_mpz_t(), static_cast<mp_bitcnt_t>(k) + 1);
  } else {
    mpz_mul_2exp(den.get_mpz_t(), den.get_mpz_t(), static_cast<mp_bitcnt_t>(-k));
    mpz_mul_2exp(num.get_mpz_t(), num.get_mpz_t(), 1);
  }
  num += den;
  den *= 2;
  mpz_fdiv_q(num.get_mpz_t(), num.get_mpz_t(), den.get_mpz_t());
  num -= t;
  return static_cast<std::int64_t>(num.get_si());
}

} // namespace

IPt GridFrame::round(const ExactPoint& p) const {
  mpz_class num, den;
  return {round_scaled(p.x, k_, tx_, num, den), round_scaled(p.y, k_, ty_, num, den)};
}

GridInput GridFrame::round(const PolygonSet& q) const {
  GridInput out;
  auto add = [&](const Ring& ring) {
    IRing r;
    r.reserve(ring.size());
    for (const auto& p : ring) r.push_back(round(p));
    out.rings.push_back(std::move(r));
  };
  for (const auto& poly : q.polygons) {
    out.first_ring.push_back(out.rings.size());
    add(poly.outer);
    for (const auto& hole : poly.holes) add(hole);
  }
  out.first_ring.push_back(out.rings.size());
  remove_repeats(out.rings);
  return out;
}

IRings GridInput::solid_rings(std::vector<std::size_t>& left_out) const {
  IRings out;
  for (std::size_t k = 0; k + 1 < first_ring.size(); ++k) {
    bool solid = true;
    for (std::size_t i = first_ring[k]; i < first_ring[k + 1] && solid; ++i) {
      // Exact: the rounded ring keeps the sign of its ring in Q (outer positive, holes negative).
      const Int128 area = rings[i].size() < 3 ? 0 : twice_area(rings[i]);
      solid = i == first_ring[k] ? area > 0 : area < 0;
    }
    if (!solid) {
      left_out.push_back(k);
      continue;
    }
    for (std::size_t i = first_ring[k]; i < first_ring[k + 1]; ++i) out.push_back(rings[i]);
  }
  return out;
}

bool GridInput::has_thin_ring() const {
  for (const IRing& ring : rings) {
    double perimeter = 0.0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const DPt a = to_d(ring[i]), b = to_d(ring[(i + 1) % ring.size()]);
      perimeter += std::hypot(b.x - a.x, b.y - a.y);
    }
    const Int128 area = ring.size() < 3 ? 0 : twice_area(ring);
    if (std::fabs(static_cast<double>(area)) <= 4.0 * kInputRounding * perimeter) return true;
  }
  return false;
}

namespace {

// (v + t) / 2^k in lowest terms without a gcd: the denominator is a power of two, so only the
// trailing zero bits of the numerator cancel (mpz_scan1 counts them, for negative numbers too).
Rational scaled_back(std::int64_t v, const mpz_class& t, int k) {
  // Fast path when v + t fits in 64 bits and the denominator in an unsigned long: the same
  // canonical value without GMP temporaries (the YES answer's P, 2% of KAZ's decision).
  long sum = 0;
  if (k > 0 && k < 64 && t.fits_slong_p() &&
      !__builtin_add_overflow(static_cast<long>(v), t.get_si(), &sum)) {
    if (sum == 0) return Rational(0);
    const int shift = std::min(std::countr_zero(static_cast<unsigned long>(sum)), k);
    Rational out;
    // sum >> shift is exact (those bits are zero) and odd unless shift = k (then den = 1).
    mpq_set_si(out.get_mpq_t(), sum >> shift, 1UL << (k - shift));
    return out;
  }
  mpz_class num = mpz_class(static_cast<long>(v)) + t;
  if (k <= 0) {
    mpz_mul_2exp(num.get_mpz_t(), num.get_mpz_t(), static_cast<mp_bitcnt_t>(-k));
    return Rational(num);
  }
  if (num == 0) return Rational(0);
  const mp_bitcnt_t shift = std::min(mpz_scan1(num.get_mpz_t(), 0), static_cast<mp_bitcnt_t>(k));
  mpz_tdiv_q_2exp(num.get_mpz_t(), num.get_mpz_t(), shift); // exact: those bits are zero
  mpz_class den;
  mpz_setbit(den.get_mpz_t(), static_cast<mp_bitcnt_t>(k) - shift);
  return Rational(num, den); // already canonical: num odd or den = 1
}

} // namespace

ExactPoint GridFrame::exact(IPt p) const {
  return {scaled_back(p.x, tx_, k_), scaled_back(p.y, ty_, k_)};
}

} // namespace penshape::fast
