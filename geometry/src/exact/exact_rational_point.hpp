// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The exact point behind a RoundedPoint, in rationals, for the exact tiers (CGAL headers: include
// only from the exact tiers' .cpp files).

#include <array>
#include <cmath>

#include <CGAL/Gmpq.h>
#include <gmpxx.h>

#include "rounded_point.hpp"

namespace clearjoint::geometry::detail {

namespace exact_rational_point_detail {

/// mantissa 2^exponent: a finite double, exactly, and the exact sums and products of such.
/// The recipe's arithmetic in this form reduces no fraction: Gmpq arithmetic took a gcd per
/// operation, which on coordinates of very different magnitudes cost more than the rest of an
/// exact circle-plane query.
struct Dyadic {
  mpz_class mantissa;
  long exponent = 0;
};

inline Dyadic of(double x) {
  int binary_exponent = 0;
  const double fraction = std::frexp(x, &binary_exponent);
  Dyadic d;
  mpz_set_d(d.mantissa.get_mpz_t(), std::ldexp(fraction, 53));  // exact: 53 bits
  d.exponent = binary_exponent - 53;
  return d;
}

/// a + b, exactly (zeros aside, the smaller exponent is kept).
inline Dyadic sum(const Dyadic& a, const Dyadic& b) {
  if (sgn(a.mantissa) == 0) return b;
  if (sgn(b.mantissa) == 0) return a;
  const Dyadic& low = a.exponent <= b.exponent ? a : b;
  const Dyadic& high = a.exponent <= b.exponent ? b : a;
  Dyadic out;
  out.exponent = low.exponent;
  mpz_mul_2exp(out.mantissa.get_mpz_t(), high.mantissa.get_mpz_t(),
               static_cast<mp_bitcnt_t>(high.exponent - low.exponent));
  out.mantissa += low.mantissa;
  return out;
}

/// The rational m 2^e (Gmpq's canonical form: mpq_div_2exp removes common twos).
inline CGAL::Gmpq rational(const Dyadic& d) {
  CGAL::Gmpq out;
  mpq_set_z(out.mpq(), d.mantissa.get_mpz_t());
  if (d.exponent > 0) mpq_mul_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(d.exponent));
  if (d.exponent < 0) mpq_div_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(-d.exponent));
  return out;
}

}  // namespace exact_rational_point_detail

/// (minuend - subtrahend + sign (length / 2) direction) * 2^-scale_exponent, exactly: the point
/// the query decides on after the kernel's power-of-two rescaling (scale_normalisation.hpp).
/// The inputs are finite doubles (validated), so every value is well defined.
inline std::array<CGAL::Gmpq, 3> exact_rational_point(const RoundedPoint& point, int scale_exponent) {
  namespace d = exact_rational_point_detail;
  // sign (length / 2): a double times +-1/2, as a dyadic.
  d::Dyadic half_length = d::of(point.length);
  half_length.exponent -= 1;
  if (point.sign < 0) half_length.mantissa = -half_length.mantissa;
  std::array<CGAL::Gmpq, 3> out;
  for (int i = 0; i < 3; ++i) {
    d::Dyadic x = d::sum(d::of(point.minuend[i]), d::of(-point.subtrahend[i]));
    if (point.sign != 0) {
      d::Dyadic offset = d::of(point.direction[i]);
      offset.mantissa *= half_length.mantissa;
      offset.exponent += half_length.exponent;
      x = d::sum(x, offset);
    }
    x.exponent -= scale_exponent;
    out[i] = d::rational(x);
  }
  return out;
}

}  // namespace clearjoint::geometry::detail
