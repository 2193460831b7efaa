// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Dyadic numbers m 2^e for the real-root isolation (real_root_isolation.hpp): exact sums,
// differences, midpoints and comparisons with no fraction ever reduced, and their enclosure as a
// Bounded for the double filters.

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "arithmetic/error_bounded.hpp"
#include "exact/exact_numbers.hpp"

namespace clearjoint::geometry::detail {

/// mantissa 2^exponent, the mantissa odd (or zero, with exponent 0): every point the isolation
/// visits is one (the bound, midpoints, doubles), and sums and halvings of them need no gcd.
struct Dyadic {
  Integer mantissa;
  long exponent = 0;

  void normalise() {
    if (sgn(mantissa) == 0) {
      exponent = 0;
      return;
    }
    const mp_bitcnt_t zeros = mpz_scan1(mantissa.get_mpz_t(), 0);
    if (zeros > 0) {
      mpz_tdiv_q_2exp(mantissa.get_mpz_t(), mantissa.get_mpz_t(), zeros);
      exponent += static_cast<long>(zeros);
    }
  }
  static Dyadic of_double(double x) {
    // Exact: a finite double is an integer of at most 53 bits times a power of two.
    int binary_exponent = 0;
    const double fraction = std::frexp(x, &binary_exponent);
    Dyadic d;
    mpz_set_d(d.mantissa.get_mpz_t(), std::ldexp(fraction, 53));
    d.exponent = binary_exponent - 53;
    d.normalise();
    return d;
  }
  static Dyadic of_rational(const Rational& x) {
    const mpz_srcptr denominator = mpq_denref(x.mpq());
    const mp_bitcnt_t power = mpz_scan1(denominator, 0);
    if (mpz_sizeinbase(denominator, 2) != power + 1) throw std::invalid_argument("isolate_real_roots: bound must be dyadic (a power of two)");
    Dyadic d;
    d.mantissa = Integer(mpq_numref(x.mpq()));
    d.exponent = -static_cast<long>(power);
    d.normalise();
    return d;
  }
  Rational to_rational() const {
    Rational r;
    mpq_set_z(r.mpq(), mantissa.get_mpz_t());
    if (exponent > 0) mpq_mul_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(exponent));
    if (exponent < 0) mpq_div_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(-exponent));
    return r;
  }
  /// CGAL::to_double of the same rational (mpq_get_d: truncation).
  double to_double() const { return CGAL::to_double(to_rational()); }
};

/// a and b with their mantissas brought to the smaller exponent.
inline std::pair<Integer, Integer> aligned(const Dyadic& a, const Dyadic& b, long& exponent) {
  exponent = std::min(a.exponent, b.exponent);
  Integer x, y;
  mpz_mul_2exp(x.get_mpz_t(), a.mantissa.get_mpz_t(), static_cast<mp_bitcnt_t>(a.exponent - exponent));
  mpz_mul_2exp(y.get_mpz_t(), b.mantissa.get_mpz_t(), static_cast<mp_bitcnt_t>(b.exponent - exponent));
  return {std::move(x), std::move(y)};
}
inline int compare(const Dyadic& a, const Dyadic& b) {
  // Different signs, or magnitudes in different binades, decide without aligning.
  const int sa = sgn(a.mantissa), sb = sgn(b.mantissa);
  if (sa != sb) return sa < sb ? -1 : 1;
  if (sa == 0) return 0;
  const long la = static_cast<long>(mpz_sizeinbase(a.mantissa.get_mpz_t(), 2)) + a.exponent;
  const long lb = static_cast<long>(mpz_sizeinbase(b.mantissa.get_mpz_t(), 2)) + b.exponent;
  if (la != lb) return (la < lb) == (sa > 0) ? -1 : 1;
  long exponent = 0;
  const auto [x, y] = aligned(a, b, exponent);
  return cmp(x, y);
}
inline bool operator<=(const Dyadic& a, const Dyadic& b) { return compare(a, b) <= 0; }
inline bool operator>(const Dyadic& a, const Dyadic& b) { return compare(a, b) > 0; }
inline Dyadic midpoint(const Dyadic& a, const Dyadic& b) {
  Dyadic m;
  const auto [x, y] = aligned(a, b, m.exponent);
  m.mantissa = x + y;
  m.exponent -= 1;
  m.normalise();
  return m;
}
inline Dyadic operator-(const Dyadic& a, const Dyadic& b) {
  Dyadic d;
  const auto [x, y] = aligned(a, b, d.exponent);
  d.mantissa = x - y;
  d.normalise();
  return d;
}
inline Dyadic operator+(const Dyadic& a, const Dyadic& b) {
  Dyadic d;
  const auto [x, y] = aligned(a, b, d.exponent);
  d.mantissa = x + y;
  d.normalise();
  return d;
}
inline Dyadic operator-(Dyadic a) {
  a.mantissa = -a.mantissa;
  return a;
}

/// x as a Bounded, or {NaN, NaN} (which decides no sign) beyond the range where the conversion
/// is plainly safe.
inline Bounded bounded(const Dyadic& x) {
  if (sgn(x.mantissa) == 0) return Bounded(0.0);
  long binary_exponent = 0;
  const double mantissa = mpz_get_d_2exp(&binary_exponent, x.mantissa.get_mpz_t());
  const long total = binary_exponent + x.exponent;
  constexpr long kSafeExponent = 1000;
  if (total > kSafeExponent || total < -kSafeExponent) {
    return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  }
  const double value = std::ldexp(mantissa, static_cast<int>(total));
  // mpz_get_d_2exp truncates to 53 bits: a relative error below 2^-52.
  return {value, mpz_sizeinbase(x.mantissa.get_mpz_t(), 2) > 53 ? std::fabs(value) * 0x1p-52 : 0.0};
}

}  // namespace clearjoint::geometry::detail
