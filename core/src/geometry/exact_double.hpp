#pragma once
// Whether a rational is a double exactly, decided without arithmetic: the grids penshape builds
// (ink polygons, offsets) have coordinates n * 2^-m with small n, so their conversions to doubles
// and their rounding bounds need no GMP division or subtraction. Decimal input (small n / d) is
// converted without GMP's division too, to the very double mpq_get_d gives.
#include <cmath>
#include <cstdint>

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

// The commonest case of the above read off the limbs: v = n / 2^k with |n| < 2^53 in one limb
// and 2^k in one (k < 64), so n and 2^-k are doubles and their product is v exactly. Sets `out`
// and returns true then; false says nothing. (No GMP calls: this is most of reading and
// validating a 200,000-vertex file's 400,000 coordinates, several times over.)
inline bool small_dyadic_to_double(const mpq_class& v, double& out) {
  const mpz_srcptr num = v.get_num_mpz_t();
  const mpz_srcptr den = v.get_den_mpz_t();
  if (mpz_size(den) != 1 || mpz_size(num) > 1 || mpz_sgn(den) < 0) return false;
  const std::uint64_t d = mpz_getlimbn(den, 0);
  const std::uint64_t n = mpz_getlimbn(num, 0); // 0 for a zero numerator
  if ((d & (d - 1)) != 0 || (n >> 53) != 0) return false;
  const double magnitude = static_cast<double>(n) * (1.0 / static_cast<double>(d));
  out = mpz_sgn(num) < 0 ? -magnitude : magnitude;
  return true;
}

// mpq_get_d's value (v truncated towards zero) without GMP's division when v = n / d with
// 0 < |n|, d < 2^53, each in one limb, d not a power of two (decimal input such as 0.123456 =
// 1929/15625): the common case of files read as text. Sets `out` and returns true then; false
// says nothing. Such a v is never is_double_exactly's case (its denominator test fails).
//
// Why it is mpq_get_d's double, bit for bit, whatever the rounding mode (the fast engine runs
// parts of its work rounding upwards): |n| and d are doubles exactly, so q = |n| / d is one of
// the two doubles around the true quotient t = |n| / d (every IEEE mode rounds to a neighbour).
// The truncation of t is q when q <= t, and q's lower neighbour when q > t. The sign of q * d - n
// tells which: fma rounds the exact q * d - n once and rounding keeps the sign of a nonzero value
// as long as it does not flush to zero. It cannot: q * d - n is an integer multiple of ulp(q)
// (q is a multiple of ulp(q), d and n are integers, ulp(q) <= 1), and q >= 2^-900 keeps ulp(q)
// far above the smallest normal double, so no denormal arises even with flush-to-zero.
inline bool small_quotient_to_double(const mpq_class& v, double& out) {
  const mpz_srcptr num = v.get_num_mpz_t();
  const mpz_srcptr den = v.get_den_mpz_t();
  if (mpz_size(den) != 1 || mpz_size(num) != 1 || mpz_sgn(den) < 0) return false;
  const std::uint64_t d = mpz_getlimbn(den, 0);
  const std::uint64_t n = mpz_getlimbn(num, 0);
  if ((d >> 53) != 0 || (n >> 53) != 0 || (d & (d - 1)) == 0) return false;
  const auto dd = static_cast<double>(d);
  const auto nd = static_cast<double>(n);
  double q = nd / dd;
  if (!(q >= 0x1p-900)) return false;
  if (std::fma(q, dd, -nd) > 0.0) q = std::nextafter(q, 0.0);
  out = mpz_sgn(num) < 0 ? -q : q;
  return true;
}

// v as a double: exactly, without GMP's division, when v is a double exactly (the common case
// above: the numerator's double is exact and the power of two scales it exactly); otherwise
// mpq_get_d's value (truncated towards zero; small quotients without GMP, as above). `exact`
// says which case it was.
inline double to_double_checked(const mpq_class& v, bool& exact) {
  if (double d = 0; small_dyadic_to_double(v, d)) {
    exact = true;
    return d;
  }
  if (double d = 0; small_quotient_to_double(v, d)) {
    exact = false; // what is_double_exactly says of a denominator that is not a power of two
    return d;
  }
  exact = is_double_exactly(v);
  if (!exact) return v.get_d();
  const std::size_t shift = mpz_sizeinbase(v.get_den_mpz_t(), 2) - 1;
  return std::ldexp(mpz_get_d(v.get_num_mpz_t()), -static_cast<int>(shift));
}

} // namespace penshape::detail
