#pragma once
// Rim angles live in [0, 2 pi).

#include <cmath>
#include <numbers>

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

/// atan2(y, x) within kApproximateAngleError, in (-pi, pi]; 0 for y = x = 0. For starting guesses
/// only, never for an answer or a bound: libm's atan2 costs ten times as much, and a guess
/// 1e-7 rad off changes nothing in a Newton iteration that starts 1e-2 rad from its root. atan(z)
/// on [0, 1] is z p(z^2), p the degree-7 Chebyshev least-squares fit of atan(z)/z in z^2 on
/// [0, 1] (numpy, 200001 points; max error 2.9e-7 rad), converted to powers; the other octants
/// by atan(z) = pi/2 - atan(1/z) and the signs of x and y.
inline double approximate_atan2(double y, double x) {
  const double ax = std::fabs(x), ay = std::fabs(y);
  const double big = ax > ay ? ax : ay, small = ax > ay ? ay : ax;
  if (big == 0.0) return 0.0;
  const double z = small / big, t = z * z;
  const double p =
      0.9999999227755191 +
      t * (-0.33332232618669755 +
           t * (0.1997402857578832 +
                t * (-0.14047821221115434 +
                     t * (0.10002205229428647 +
                          t * (-0.060874481860006865 + t * (0.025331700814268776 + t * -0.005021063842473555))))));
  double angle = z * p;
  if (ay > ax) angle = 0.5 * std::numbers::pi - angle;
  if (x < 0.0) angle = std::numbers::pi - angle;
  return y < 0.0 ? -angle : angle;
}

/// acos(c) within kApproximateAngleError for c in [-1, 1] (clamped), in [0, pi]: the angle of
/// (c, sqrt(1 - c^2)). Starting guesses only, as approximate_atan2.
inline double approximate_acos(double c) {
  const double x = c < -1.0 ? -1.0 : (c > 1.0 ? 1.0 : c);
  return approximate_atan2(std::sqrt((1.0 - x) * (1.0 + x)), x);
}

}  // namespace clearjoint::geometry::detail
