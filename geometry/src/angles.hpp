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

}  // namespace clearjoint::geometry::detail
