// SPDX-License-Identifier: BSD-3-Clause
#include "arithmetic/scale_normalisation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace clearjoint::geometry::detail {
namespace {

TEST(DirectionScaled, BringsTheLargestComponentIntoOneToTwoExactly) {
  const Vector3 v(3e-170, -5e-171, 0.0);
  const Vector3 s = direction_scaled(v);
  EXPECT_GE(s.cwiseAbs().maxCoeff(), 1.0);
  EXPECT_LT(s.cwiseAbs().maxCoeff(), 2.0);
  // Exact: the ratio of components is unchanged to the last bit.
  EXPECT_EQ(s.x() / s.y(), v.x() / v.y());
}

TEST(DirectionScaled, LeavesAVectorAloneWhenScalingWouldLoseBits) {
  // Scaling 1e300 down to ~1 would push 1e-310 (subnormal already) further down: not exact.
  const Vector3 v(1e300, 4.9e-324, 0.0);
  EXPECT_EQ(direction_scaled(v), v);
}

TEST(LengthExponent, IsZeroForOrdinaryLengthsAndTheBinaryExponentForExtremeOnes) {
  EXPECT_EQ(length_exponent(0.01), 0);
  EXPECT_EQ(length_exponent(1e3), 0);
  EXPECT_EQ(length_exponent(1e300), std::ilogb(1e300));
  EXPECT_EQ(length_exponent(1e-300), std::ilogb(1e-300));
}

}  // namespace
}  // namespace clearjoint::geometry::detail
