#pragma once
// Rim angles live in [0, 2 pi).

#include <cmath>
#include <numbers>

namespace clearjoint::geometry::detail {

inline constexpr double kTwoPi = 2 * std::numbers::pi;

/// The representative of `angle` in [0, 2 pi) (2 pi itself, after rounding, maps to 0).
inline double wrap_angle(double angle) {
  double a = std::fmod(angle, kTwoPi);
  if (a < 0) a += kTwoPi;
  if (a >= kTwoPi) a = 0.0;
  return a;
}

}  // namespace clearjoint::geometry::detail
