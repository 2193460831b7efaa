// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The exact point behind a RoundedPoint, in rationals, for the exact tiers (CGAL headers: include
// only from the exact tiers' .cpp files).

#include <array>
#include <cmath>

#include <CGAL/Gmpq.h>

#include "rounded_point.hpp"

namespace clearjoint::geometry::detail {

/// (minuend - subtrahend + sign (length / 2) direction) * 2^-scale_exponent, exactly: the point
/// the query decides on after the kernel's power-of-two rescaling (scale_normalisation.hpp).
/// The inputs are finite doubles (validated), so every Gmpq is well defined.
inline std::array<CGAL::Gmpq, 3> exact_rational_point(const RoundedPoint& point, int scale_exponent) {
  using Rational = CGAL::Gmpq;
  // 2^-e as a rational: from the double 2^-|e| (exact: length_exponent keeps |e| <= 1074, where
  // 2^-|e| is still a double), inverted when e is negative.
  const Rational power(std::ldexp(1.0, -std::abs(scale_exponent)));
  const Rational scale = scale_exponent >= 0 ? power : Rational(1) / power;
  const Rational half_length = Rational(point.length) / Rational(2);
  std::array<Rational, 3> out;
  for (int i = 0; i < 3; ++i) {
    Rational x = Rational(point.minuend[i]) - Rational(point.subtrahend[i]);
    if (point.sign != 0) x += Rational(point.sign) * half_length * Rational(point.direction[i]);
    out[i] = x * scale;
  }
  return out;
}

}  // namespace clearjoint::geometry::detail
