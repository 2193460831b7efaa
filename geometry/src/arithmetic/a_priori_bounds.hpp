// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A priori error bounds in plain double (Higham, "Accuracy and Stability of Numerical
// Algorithms", Lemma 3.3 and sec. 3.1): an expression of + - * / on exact doubles, computed in
// double, is within gamma_k of its absolute-value twin (the same expression on |inputs| with
// subtractions turned into additions), k the longest chain of roundings in it, provided nothing
// underflows or overflows. The twin costs one extra operation per operation, far less than the
// running error of error_bounded.hpp, so the hot paths use this wherever the guard below holds
// and fall back to the running error where it does not.

#include <cmath>

#include "arithmetic/error_bounded.hpp"
#include "arithmetic/twinned.hpp"
#include "clearjoint/geometry/arithmetic/vector3.hpp"

namespace clearjoint::geometry::detail {

/// Higham's gamma_k = k u / (1 - k u). Every use below counts a chain under 40; gamma_64 leaves
/// room for a miscount and costs nothing measurable in filter failures.
inline constexpr double kGamma64 = 64 * kUnitRoundoff / (1 - 64 * kUnitRoundoff);
/// The absolute-value twins are themselves rounded (relative 24 u at most): inflate.
inline constexpr double kMagnitudeInflation = 1 + 0x1p-40;
/// Inputs with magnitudes in [2^-100, 2^100] (or zero) keep every product of up to 8 factors
/// (the longest in the kernel) normal and finite: 2^(8*100) < 2^1023 and 2^(-8*100) > 2^-1022.
inline constexpr double kSmallestGuardedInput = 0x1p-100;
inline constexpr double kLargestGuardedInput = 0x1p100;

/// The absolute-value twin of a x b, for |a| and |b|.
inline Vector3 abs_cross(const Vector3& a, const Vector3& b) {
  return {a.y() * b.z() + a.z() * b.y(), a.z() * b.x() + a.x() * b.z(),
          a.x() * b.y() + a.y() * b.x()};
}

/// The a priori bound gamma_64 * magnitude, inflated for the twin's own rounding; for V = double
/// or Pair (a bound per lane).
template <class V>
V a_priori_bound(V magnitude) {
  return kGamma64 * magnitude * kMagnitudeInflation;
}

/// A computed value with its a priori bound, as a Bounded.
inline Bounded a_priori(double value, double magnitude) { return {value, a_priori_bound(magnitude)}; }

/// Underflow allowance for a priori bounds whose guard checks only the upper limit (every input
/// at most 2^100 in magnitude, however small). Higham's model with underflow (sec. 2.1): a
/// rounded product is (x y)(1 + delta) + eta with |eta| <= 2^-1075, and sums and differences that
/// underflow are exact. In the circle-plane quantities and the candidate prefilters (no
/// reciprocals; the longest chain s s |n_c|^2) each eta is multiplied afterwards by at most two
/// factors below 2^202, so their few dozen etas add less than 2^6 * 2^-1075 * 2^404 = 2^-665 to any
/// quantity: 2^-600 covers them with room, and is negligible beside any bound of inputs above
/// ~1e-150 in magnitude. Tiny non-zero inputs are then harmless, and the guard need not test a
/// lower limit per value (26 values, ~9 instructions each, in the prefilters).
inline constexpr double kUnderflowAllowance = 0x1p-600;
/// a_priori_bound plus kUnderflowAllowance.
template <class V>
V a_priori_bound_with_underflow(V magnitude) {
  return a_priori_bound(magnitude) + kUnderflowAllowance;
}
inline Bounded a_priori_with_underflow(double value, double magnitude) {
  return {value, a_priori_bound_with_underflow(magnitude)};
}

/// Whether x's a priori bound proves it positive, for inputs inside the full guard (nothing
/// underflows). A bool for V = double, a lane mask for Pair.
template <class V>
auto a_priori_proves_positive(const ValueAndTwin<V>& x) {
  return x.value > a_priori_bound(x.twin);
}
/// The same with kUnderflowAllowance, for guards that test only the upper limit.
template <class V>
auto a_priori_proves_positive_with_underflow(const ValueAndTwin<V>& x) {
  return x.value > a_priori_bound_with_underflow(x.twin);
}
/// x with its a priori bound (and kUnderflowAllowance) as a Bounded, or a PairBounded for V = Pair.
inline Bounded a_priori_with_underflow(const ValueAndTwin<double>& x) { return a_priori_with_underflow(x.value, x.twin); }
inline PairBounded a_priori_with_underflow(const ValueAndTwin<Pair>& x) {
  return {x.value, a_priori_bound_with_underflow(x.twin)};
}

}  // namespace clearjoint::geometry::detail
