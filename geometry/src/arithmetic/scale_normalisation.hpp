// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Exact rescaling by powers of two before a query. A normal or axis means only its direction,
// and a uniform scale of all lengths by 2^k changes no topology; multiplying by 2^k is exact
// unless a component under- or overflows, which is checked. This keeps the double-precision
// steps of every tier (and the exact tier's mapping back to angles) away from under- and
// overflow: a 1e-170 normal otherwise squares to zero.

#include <bit>
#include <cmath>
#include <cstdint>

#include "clearjoint/geometry/arithmetic/vector3.hpp"

namespace clearjoint::geometry::detail {

/// Lengths whose binary exponent is within this of 0 are left alone (the a priori bounds of
/// rim_distance_polynomial.cpp accept magnitudes in [2^-100, 2^100]).
inline constexpr int kLengthExponentSlack = 60;

/// The binary exponent of a normal double (floor(log2 |x|)), read from its bits: std::ilogb and
/// std::ldexp are out-of-line libm calls that cost more than the rest of a cheap query.
inline int normal_exponent(double x) {
  return static_cast<int>((std::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff) - 1023;
}
inline bool is_normal_nonzero(double x) {
  const auto field = (std::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff;
  return field != 0 && field != 0x7ff;
}
/// 2^k, exactly, for -1022 <= k <= 1023.
inline double power_of_two(int k) {
  return std::bit_cast<double>(static_cast<std::uint64_t>(1023 + k) << 52);
}

/// v * 2^-e with e the exponent of its largest component (so that component is in [1, 2)), when
/// that is exact; v itself otherwise.
inline Vector3 direction_scaled(const Vector3& v) {
  const double largest = v.cwiseAbs().maxCoeff();
  if (is_normal_nonzero(largest)) {
    const int e = normal_exponent(largest);
    if (e == 0) return v;
    if (e > -1022 && e < 1023) {
      // Fast path: one multiplication by an exact power of two, checked by the inverse one
      // (a component that underflows to a subnormal loses bits and fails the check).
      const double down = power_of_two(-e), up = power_of_two(e);
      const Vector3 scaled = v * down;
      return scaled * up == v ? scaled : v;
    }
  }
  if (largest == 0.0 || !std::isfinite(largest)) return v;
  const int e = std::ilogb(largest);
  if (e == 0) return v;
  const Vector3 scaled(std::ldexp(v.x(), -e), std::ldexp(v.y(), -e), std::ldexp(v.z(), -e));
  const bool exact = std::ldexp(scaled.x(), e) == v.x() && std::ldexp(scaled.y(), e) == v.y() &&
                     std::ldexp(scaled.z(), e) == v.z();
  return exact ? scaled : v;
}

/// Largest lengths in [kSmallestUnscaledLength, kLargestUnscaledLength) are left alone.
inline constexpr double kSmallestUnscaledLength = 0x1p-60, kLargestUnscaledLength = 0x1p61;
static_assert(kLengthExponentSlack == 60);  // the two limits above are 2^-60 and 2^(60 + 1)

/// The power of two 2^-e to multiply every length by (0 when none is needed or it would not be
/// exact), from the largest length given.
inline int length_exponent(double largest_length) {
  if (largest_length >= kSmallestUnscaledLength && largest_length < kLargestUnscaledLength) return 0;
  if (largest_length == 0.0 || !std::isfinite(largest_length)) return 0;
  const int e = std::ilogb(largest_length);
  return (e > kLengthExponentSlack || e < -kLengthExponentSlack) ? e : 0;
}

inline bool scales_exactly(double x, int e) {
  return std::ldexp(std::ldexp(x, -e), e) == x;
}
inline bool scales_exactly(const Vector3& v, int e) {
  return scales_exactly(v.x(), e) && scales_exactly(v.y(), e) && scales_exactly(v.z(), e);
}
inline Vector3 scaled(const Vector3& v, int e) {
  return {std::ldexp(v.x(), -e), std::ldexp(v.y(), -e), std::ldexp(v.z(), -e)};
}

}  // namespace clearjoint::geometry::detail
