#pragma once
// Whether a rational is a double exactly, decided without arithmetic: the grids penshape builds
// (ink polygons, offsets) have coordinates n * 2^-m with small n, so their conversions to doubles
// and their rounding bounds need no GMP division or subtraction.
#include <cmath>

#include <gmpxx.h>

namespace penshape::detail {

// v = n / 2^k with |n| < 2^53 and k < 1000: a normal double (or zero), which mpq_get_d returns
// exactly. False says nothing (the value may still be a double).
inline bool is_double_exactly(const mpq_class& v) {
  const mpz_srcptr num = v.get_num_mpz_t();
  const mpz_srcptr den = v.get_den_mpz_t();
  const std::size_t den_bits = mpz_sizeinbase(den, 2);
  return mpz_sizeinbase(num, 2) <= 53 && den_bits < 1000 && mpz_sgn(den) > 0 &&
         mpz_scan1(den, 0) + 1 == den_bits;
}

// v as a double: exactly, without GMP's division, when v is a double exactly (the common case
// above: the numerator's double is exact and the power of two scales it exactly); otherwise
// mpq_get_d's value (truncated towards zero). `exact` says which case it was.
inline double to_double_checked(const mpq_class& v, bool& exact) {
  exact = is_double_exactly(v);
  if (!exact) return v.get_d();
  const std::size_t shift = mpz_sizeinbase(v.get_den_mpz_t(), 2) - 1;
  return std::ldexp(mpz_get_d(v.get_num_mpz_t()), -static_cast<int>(shift));
}

} // namespace penshape::detail
