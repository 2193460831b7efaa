// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Exact sums and products of doubles as integers times powers of two, for the exact tiers (GMP:
// include only from the exact tiers' .cpp files). Every input of the kernel is a double, and the
// exact tiers' quantities are sums of products of them: in this form no operation reduces a
// fraction, where CGAL::Gmpq takes a gcd per operation, which on inputs of very different
// magnitudes cost more than the rest of an exact query.

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include <CGAL/Gmpq.h>
#include <gmpxx.h>
#include <mpfr.h>

namespace clearjoint::geometry::detail {

/// mantissa 2^exponent, exactly.
struct ExactDyadic {
  mpz_class mantissa;
  long exponent = 0;
};

/// The same value with an odd mantissa (or zero): the integers at a common exponent
/// (integers_at_common_exponent) then carry no needless factors of two.
inline void strip_twos(ExactDyadic& d) {
  if (sgn(d.mantissa) == 0) return;
  const mp_bitcnt_t zeros = mpz_scan1(d.mantissa.get_mpz_t(), 0);
  if (zeros == 0) return;
  mpz_tdiv_q_2exp(d.mantissa.get_mpz_t(), d.mantissa.get_mpz_t(), zeros);
  d.exponent += static_cast<long>(zeros);
}

/// A finite double, exactly (an integer of at most 53 bits times a power of two), odd mantissa.
inline ExactDyadic exact_dyadic(double x) {
  int binary_exponent = 0;
  const double fraction = std::frexp(x, &binary_exponent);
  ExactDyadic d;
  mpz_set_d(d.mantissa.get_mpz_t(), std::ldexp(fraction, 53));  // exact: 53 bits
  d.exponent = binary_exponent - 53;
  strip_twos(d);
  return d;
}

/// a + b, exactly (zeros aside, at the smaller exponent).
inline ExactDyadic exact_sum(const ExactDyadic& a, const ExactDyadic& b) {
  if (sgn(a.mantissa) == 0) return b;
  if (sgn(b.mantissa) == 0) return a;
  const ExactDyadic& low = a.exponent <= b.exponent ? a : b;
  const ExactDyadic& high = a.exponent <= b.exponent ? b : a;
  ExactDyadic out;
  out.exponent = low.exponent;
  mpz_mul_2exp(out.mantissa.get_mpz_t(), high.mantissa.get_mpz_t(),
               static_cast<mp_bitcnt_t>(high.exponent - low.exponent));
  out.mantissa += low.mantissa;
  return out;
}

/// a b, exactly.
inline ExactDyadic exact_product(const ExactDyadic& a, const ExactDyadic& b) {
  return {a.mantissa * b.mantissa, a.exponent + b.exponent};
}

/// The rational m 2^e in Gmpq's canonical form (mpq_div_2exp removes the common twos).
inline CGAL::Gmpq exact_rational(const ExactDyadic& d) {
  CGAL::Gmpq out;
  mpq_set_z(out.mpq(), d.mantissa.get_mpz_t());
  if (d.exponent > 0) mpq_mul_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(d.exponent));
  if (d.exponent < 0) mpq_div_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(-d.exponent));
  return out;
}

/// CGAL::to_interval of the rational x 2^shift / d (d > 0), without forming that rational, whose
/// reduction takes a gcd: the double nearest to it away from zero (MPFR, round away), beside its
/// neighbour towards zero unless that rounding was exact. MPFR's correctly rounded x / d at 53
/// bits, times 2^shift, is that double wherever the result is a normal double (a power of two
/// commutes with the rounding there); elsewhere (subnormal, or beyond the double range) the
/// rational is formed and CGAL::to_interval decides.
inline std::pair<double, double> interval_of_quotient(const mpz_class& x, long shift, const mpz_class& d) {
  if (sgn(x) == 0) return {0.0, 0.0};
  const auto bits = [](const mpz_class& n) {
    return std::max<mpfr_prec_t>(static_cast<mpfr_prec_t>(mpz_sizeinbase(n.get_mpz_t(), 2)), MPFR_PREC_MIN);
  };
  mpfr_t numerator, denominator, quotient;
  mpfr_init2(numerator, bits(x));
  mpfr_init2(denominator, bits(d));
  mpfr_init2(quotient, 53);
  mpfr_set_z(numerator, x.get_mpz_t(), MPFR_RNDN);  // exact: as many bits as x
  mpfr_set_z(denominator, d.get_mpz_t(), MPFR_RNDN);
  const int inexact = mpfr_div(quotient, numerator, denominator, MPFR_RNDA);
  // The result lies in [2^(exponent - 1), 2^exponent); normal doubles in [2^-1022, 2^1024).
  const long exponent = mpfr_get_exp(quotient) + shift;
  const bool normal = exponent >= -1021 && exponent <= 1024;
  double away = 0.0;
  if (normal) {
    mpfr_mul_2si(quotient, quotient, shift, MPFR_RNDN);  // exact: MPFR's exponent range is wider
    away = mpfr_get_d(quotient, MPFR_RNDN);              // exact: a normal double's 53 bits
  }
  mpfr_clears(numerator, denominator, quotient, static_cast<mpfr_ptr>(nullptr));
  if (!normal) {
    CGAL::Gmpq value;
    mpq_set_num(value.mpq(), x.get_mpz_t());
    mpq_set_den(value.mpq(), d.get_mpz_t());
    mpq_canonicalize(value.mpq());
    if (shift > 0) mpq_mul_2exp(value.mpq(), value.mpq(), static_cast<mp_bitcnt_t>(shift));
    if (shift < 0) mpq_div_2exp(value.mpq(), value.mpq(), static_cast<mp_bitcnt_t>(-shift));
    return CGAL::to_interval(value);
  }
  if (inexact == 0) return {away, away};
  const double toward = std::nextafter(away, 0.0);
  return away < 0 ? std::pair<double, double>(away, toward) : std::pair<double, double>(toward, away);
}

/// CGAL::to_interval of x 2^shift (an integer times a power of two), without MPFR: the double
/// nearest to it away from zero beside its neighbour towards zero, or that one double where it is
/// exact. mpz_get_d_2exp truncates to 53 bits, which is the neighbour towards zero; the value is
/// exact when no set bit lies below the top 53. Empty where the result is not safely a normal
/// double (then the caller forms the rational and CGAL decides). CGAL converts a Gmpq through
/// mpfr_set_q, whose cost (a division of the numerator by the denominator at 53 bits) dominated
/// the exact tier's conversions of dyadic rationals: the isolation's endpoints, the conic's a, b
/// and r^2.
inline std::optional<std::pair<double, double>> interval_of_dyadic(mpz_srcptr x, long shift) {
  if (mpz_sgn(x) == 0) return std::pair<double, double>(0.0, 0.0);
  const long bits = static_cast<long>(mpz_sizeinbase(x, 2));
  // |x 2^shift| lies in [2^(bits + shift - 1), 2^(bits + shift)); normal doubles from 2^-1022 up,
  // finite below 2^1024. One binade of room at each end keeps the neighbours normal and finite.
  if (bits + shift - 1 < -1021 || bits + shift > 1023) return std::nullopt;
  long binary_exponent = 0;
  const double fraction = mpz_get_d_2exp(&binary_exponent, x);  // truncated: |fraction| in [1/2, 1)
  const double toward = std::ldexp(fraction, static_cast<int>(binary_exponent + shift));  // exact
  const bool exact = bits <= 53 || static_cast<long>(mpz_scan1(x, 0)) >= bits - 53;
  if (exact) return std::pair<double, double>(toward, toward);
  const double away = std::nextafter(toward, mpz_sgn(x) > 0 ? HUGE_VAL : -HUGE_VAL);
  return mpz_sgn(x) > 0 ? std::pair<double, double>(toward, away) : std::pair<double, double>(away, toward);
}

/// CGAL::to_interval(x), through interval_of_dyadic where x's denominator is a power of two.
inline std::pair<double, double> interval_of(const CGAL::Gmpq& x) {
  const mpz_srcptr denominator = mpq_denref(x.mpq());
  const mp_bitcnt_t twos = mpz_scan1(denominator, 0);
  if (twos + 1 == mpz_sizeinbase(denominator, 2)) {  // denominator == 2^twos
    if (const auto range = interval_of_dyadic(mpq_numref(x.mpq()), -static_cast<long>(twos))) return *range;
  }
  return CGAL::to_interval(x);
}

/// Values x_i that all share one exponent E (the smallest exponent of a nonzero one; 0 when all
/// are zero), as the integers x_i 2^-E. A polynomial homogeneous of degree k in the x_i takes the
/// value 2^(-k E) times its value at the x_i at these integers: the same sign, and no fraction
/// formed on the way.
template <std::size_t N>
struct IntegersAtCommonExponent {
  std::array<mpz_class, N> integers;
  long exponent = 0;
};
template <std::size_t N>
IntegersAtCommonExponent<N> integers_at_common_exponent(const std::array<ExactDyadic, N>& values) {
  IntegersAtCommonExponent<N> out;
  bool any = false;
  for (const ExactDyadic& d : values) {
    if (sgn(d.mantissa) == 0) continue;
    out.exponent = any ? std::min(out.exponent, d.exponent) : d.exponent;
    any = true;
  }
  for (std::size_t i = 0; i < N; ++i) {
    if (sgn(values[i].mantissa) == 0) continue;
    mpz_mul_2exp(out.integers[i].get_mpz_t(), values[i].mantissa.get_mpz_t(),
                 static_cast<mp_bitcnt_t>(values[i].exponent - out.exponent));
  }
  return out;
}

}  // namespace clearjoint::geometry::detail
