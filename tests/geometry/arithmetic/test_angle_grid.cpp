// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/arithmetic/angle_grid.hpp: every table entry is the double nearest to the exact
// cosine and sine of its grid angle (256-bit MPFR), and grid_angle splits every angle exactly.

#include "arithmetic/angle_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "mpfr_reference.hpp"

namespace clearjoint::geometry::detail {
namespace {

using internal_testing::Real;

/// True when `value` is the double nearest to `exact` (neither neighbour is closer).
bool is_nearest_double(double value, const Real& exact) {
  const Real gap = abs(Real(value) - exact);
  return gap <= abs(Real(std::nextafter(value, HUGE_VAL)) - exact) &&
         gap <= abs(Real(std::nextafter(value, -HUGE_VAL)) - exact);
}

TEST(AngleGrid, HoldsTheCorrectlyRoundedCosineAndSineOfEveryGridAngle) {
  for (int j = 0; j < static_cast<int>(kAngleGrid.size()); ++j) {
    const Real angle = Real(j) / 16;
    EXPECT_TRUE(is_nearest_double(kAngleGrid[j].cos, cos(angle))) << "cos(" << j << "/16)";
    EXPECT_TRUE(is_nearest_double(kAngleGrid[j].sin, sin(angle))) << "sin(" << j << "/16)";
  }
}

void expect_exact_split(double theta, double wrapped) {
  const GridAngle split = grid_angle(theta);
  EXPECT_EQ(split.base.angle + split.offset, wrapped) << theta;
  // The sum above is rounded; the split is exact when the rounded difference gives it back.
  EXPECT_EQ(wrapped - split.base.angle, split.offset) << theta;
  EXPECT_LE(std::fabs(split.offset), kAngleGridStep / 2) << theta;
  const int j = static_cast<int>(split.base.angle * 16);
  EXPECT_EQ(split.base.angle, j / 16.0) << theta;
  EXPECT_EQ(split.base.cos, kAngleGrid[j].cos) << theta;
  EXPECT_EQ(split.base.sin, kAngleGrid[j].sin) << theta;
  // Exactness checked in exact arithmetic: the real base + offset is the wrapped angle.
  EXPECT_TRUE(Real(split.base.angle) + Real(split.offset) == Real(wrapped)) << theta;
}

TEST(AngleGrid, SplitsEveryAngleExactlyIntoAGridAngleAndAnOffsetOfAtMostHalfAStep) {
  for (const double theta : {0.0, 1e-300, 0x1p-1074, 1.0 / 32, std::nextafter(1.0 / 32, 0.0),
                             std::nextafter(1.0 / 32, 1.0), 3.0 / 32, 0.5, 1.0, 3.14159,
                             std::nextafter(kTwoPi, 0.0), 100.5 / 16}) {
    expect_exact_split(theta, theta);
  }
  std::mt19937_64 rng(211);
  std::uniform_real_distribution<double> angle(0.0, kTwoPi);
  for (int i = 0; i < 100000; ++i) {
    const double theta = angle(rng);
    expect_exact_split(theta, theta);
  }
}

TEST(AngleGrid, WrapsAnglesOutsideOneTurnFirst) {
  for (const double theta : {-1e-3, -1.0, -6.0, 7.0, 12.0, 1e6, -1e6}) {
    expect_exact_split(theta, wrap_angle(theta));
  }
}

TEST(AngleGrid, GivesNaNForNonFiniteAngles) {
  for (const double theta : {std::numeric_limits<double>::quiet_NaN(), HUGE_VAL, -HUGE_VAL}) {
    const GridAngle split = grid_angle(theta);
    EXPECT_TRUE(std::isnan(split.base.angle) && std::isnan(split.offset) &&
                std::isnan(split.base.cos) && std::isnan(split.base.sin))
        << theta;
  }
}

}  // namespace
}  // namespace clearjoint::geometry::detail
