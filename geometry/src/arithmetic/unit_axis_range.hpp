// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Where unit_axis (joint_geometry.cpp) normalises an axis directly, a / sqrt(|a|^2): for callers
// that compute |a|^2 themselves and must get the same unit axis bit for bit (detect_contacts'
// free-flight proof).

namespace clearjoint::geometry::detail {

/// |a|^2 outside these bounds would lose precision to underflow or overflow; inside them a is
/// finite and non-zero (NaN fails both comparisons).
inline constexpr double kSmallestSafeSquare = 0x1p-1000, kLargestSafeSquare = 0x1p1000;
inline bool in_safe_square_range(double squared) {
  return (squared > kSmallestSafeSquare) & (squared < kLargestSafeSquare);
}

}  // namespace clearjoint::geometry::detail
