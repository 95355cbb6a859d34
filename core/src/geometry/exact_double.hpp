#pragma once
// Whether a rational is a double exactly, decided without arithmetic: the grids penshape builds
// (ink polygons, offsets) have coordinates n * 2^-m with small n, so their conversions to doubles
// and their rounding bounds need no GMP division or subtraction.
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

} // namespace penshape::detail
