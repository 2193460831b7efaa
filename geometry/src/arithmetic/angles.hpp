// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Rim angles live in [0, 2 pi).

#include <cmath>
#include <numbers>

#include "arithmetic/pair_lanes.hpp"

namespace clearjoint::geometry::detail {

inline constexpr double kTwoPi = 2 * std::numbers::pi;

/// The representative of `angle` in [0, 2 pi) (2 pi itself, after rounding, maps to 0).
/// Angles within one turn of [0, 2 pi) (all the kernel produces) take one addition or
/// subtraction of the rounded 2 pi instead of an fmod call; either way the result differs from
/// the true representative by the rounding of 2 pi and at most one rounding of the sum.
inline double wrap_angle(double angle) {
  double a = angle;
  if (a >= 0.0 && a < kTwoPi) return a;
  if (a >= -kTwoPi && a < 2 * kTwoPi) {
    a = a < 0.0 ? a + kTwoPi : a - kTwoPi;  // the subtraction is exact (Sterbenz)
  } else {
    a = std::fmod(angle, kTwoPi);  // exact
    if (a < 0.0) a += kTwoPi;
  }
  if (a >= kTwoPi) a = 0.0;  // a tiny negative angle plus 2 pi rounds to 2 pi
  return a;
}

/// Largest error of approximate_atan2 and approximate_acos, in radians (the fit's 2.9e-7 plus
/// rounding; test_angles.cpp measures it).
inline constexpr double kApproximateAngleError = 4e-7;

/// The fit's z p(z^2), for double or, lane by lane, Pair. p in Estrin's form, pairs of terms
/// combined by t^2 and t^4: the guess heads the chain that tier 1's first Halley step waits
/// for, and Horner's form was seven dependent multiply-adds (~42 cycles) where this is four
/// (~21). Its rounding, like Horner's, is a few ulps of an angle at most pi/4, far inside the
/// fit's 2.9e-7.
template <class T>
T approximate_atan_of_ratio(T z) {
  const T t = z * z;
  const T t2 = t * t, t4 = t2 * t2;
  const T low = (0.9999999227755191 + t * -0.33332232618669755) + t2 * (0.1997402857578832 + t * -0.14047821221115434);
  const T high = (0.10002205229428647 + t * -0.060874481860006865) +
                 t2 * (0.025331700814268776 + t * -0.005021063842473555);
  return z * (low + t4 * high);
}

/// atan2(y, x) within kApproximateAngleError, in (-pi, pi]; 0 for y = x = 0. For starting guesses
/// only, never for an answer or a bound: libm's atan2 costs ten times as much, and a guess
/// 1e-7 rad off changes nothing in an iteration that starts 1e-3 rad from its root. atan(z)
/// on [0, 1] is z p(z^2), p the degree-7 Chebyshev least-squares fit of atan(z)/z in z^2 on
/// [0, 1] (numpy, 200001 points; max error 2.9e-7 rad), converted to powers; the other octants
/// by atan(z) = pi/2 - atan(1/z) and the signs of x and y.
inline double approximate_atan2(double y, double x) {
  const double ax = std::fabs(x), ay = std::fabs(y);
  const double big = ax > ay ? ax : ay, small = ax > ay ? ay : ax;
  if (big == 0.0) return 0.0;
  double angle = approximate_atan_of_ratio(small / big);
  if (ay > ax) angle = 0.5 * std::numbers::pi - angle;
  if (x < 0.0) angle = std::numbers::pi - angle;
  return y < 0.0 ? -angle : angle;
}

/// approximate_atan2 of two (y, x) pairs at once, lane i bit for bit approximate_atan2(y[i], x[i]),
/// its branches as lane selects: tier 1 (certified_rim_roots.cpp) takes both of its angles here.
/// Which octant each lands in depends on the pose: as branches they were mispredicted about once
/// per crossing rim (callgrind's branch simulator, ~2.6 per in-contact detection with wrap_angle).
inline Pair approximate_atan2(Pair y, Pair x) {
  const Pair ax = magnitude(x), ay = magnitude(y);
  const PairMask x_bigger = ax > ay;
  const Pair big = select(x_bigger, ax, ay), small = select(x_bigger, ay, ax);
  // 0 / 0 in a lane whose inputs are both zero: NaN there, replaced by 0 at the end.
  Pair angle = approximate_atan_of_ratio(small / big);
  angle = select(ay > ax, 0.5 * std::numbers::pi - angle, angle);
  angle = select(x < 0.0, std::numbers::pi - angle, angle);
  angle = select(y < 0.0, -angle, angle);
  return select(big == 0.0, Pair{0.0, 0.0}, angle);
}

/// acos(c) within kApproximateAngleError for c in [-1, 1] (clamped), in [0, pi]. Starting
/// guesses only, as approximate_atan2. acos(a) = sqrt(1 - a) q(a) on [0, 1], q the degree-7
/// polynomial of Abramowitz and Stegun, Handbook of Mathematical Functions (1964), 4.4.46
/// (error at most 2e-8; 2.2e-8 measured at 200001 points, which test_angles.cpp bounds), in
/// Estrin's form; acos(-a) = pi - acos(a). Not approximate_atan2 of (sqrt(1 - c^2), c): that is a
/// square root, a division and the arctangent's polynomial in a row, where this is a square root
/// beside a polynomial, on the chain tier 1's first Halley step waits for.
inline double approximate_acos(double c) {
  const double x = c < -1.0 ? -1.0 : (c > 1.0 ? 1.0 : c);
  const double a = std::fabs(x), a2 = a * a, a4 = a2 * a2;
  const double q = ((1.5707963050 + a * -0.2145988016) + a2 * (0.0889789874 + a * -0.0501743046)) +
                   a4 * ((0.0308918810 + a * -0.0170881256) + a2 * (0.0066700901 + a * -0.0012624911));
  const double angle = std::sqrt(1.0 - a) * q;
  return x < 0.0 ? std::numbers::pi - angle : angle;
}

/// {approximate_atan2(y, x), approximate_acos(c)}, bit for bit: tier 1's two starting angles
/// (certified_rim_roots.cpp). The arctangent in lanes (both lanes the same: its branches as
/// selects), the arccosine beside it.
inline Pair approximate_atan2_and_acos(double y, double x, double c) {
  return Pair{approximate_atan2(Pair{y, y}, Pair{x, x})[0], approximate_acos(c)};
}

}  // namespace clearjoint::geometry::detail
