// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The exact point behind a RoundedPoint, for the exact tiers (CGAL and GMP headers: include only
// from the exact tiers' .cpp files).

#include <array>

#include <CGAL/Gmpq.h>

#include "arithmetic/rounded_point.hpp"
#include "exact/exact_dyadic.hpp"

namespace clearjoint::geometry::detail {

/// (minuend - subtrahend + sign (length / 2) direction) * 2^-scale_exponent, exactly: the point
/// the query decides on after the kernel's power-of-two rescaling (scale_normalisation.hpp).
/// The inputs are finite doubles (validated), so every value is well defined.
inline std::array<ExactDyadic, 3> exact_dyadic_point(const RoundedPoint& point, int scale_exponent) {
  // sign (length / 2): the double times +-1/2.
  ExactDyadic half_length = exact_dyadic(point.length);
  half_length.exponent -= 1;
  if (point.sign < 0) half_length.mantissa = -half_length.mantissa;
  std::array<ExactDyadic, 3> out;
  for (int i = 0; i < 3; ++i) {
    ExactDyadic x = exact_sum(exact_dyadic(point.minuend[i]), exact_dyadic(-point.subtrahend[i]));
    if (point.sign != 0) x = exact_sum(x, exact_product(exact_dyadic(point.direction[i]), half_length));
    x.exponent -= scale_exponent;
    strip_twos(x);
    out[i] = std::move(x);
  }
  return out;
}

/// The same point in rationals.
inline std::array<CGAL::Gmpq, 3> exact_rational_point(const RoundedPoint& point, int scale_exponent) {
  const std::array<ExactDyadic, 3> x = exact_dyadic_point(point, scale_exponent);
  return {exact_rational(x[0]), exact_rational(x[1]), exact_rational(x[2])};
}

}  // namespace clearjoint::geometry::detail
