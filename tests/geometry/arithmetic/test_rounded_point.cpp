// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/arithmetic/rounded_point.hpp (and the exact rebuild of exact_rational_point.hpp):
// the error bound of a rounded base or rim centre must hold against the exact point, computed
// in rationals, on ordinary, far-from-origin, tiny and huge inputs.

#include "arithmetic/rounded_point.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include <CGAL/Gmpq.h>

#include "exact/exact_rational_point.hpp"

namespace clearjoint::geometry::detail {
namespace {

using Rational = CGAL::Gmpq;

/// |exact - value|^2 <= error^2, decided exactly.
bool error_holds(const RoundedPoint& point) {
  const std::array<Rational, 3> exact = exact_rational_point(point, 0);
  Rational distance2 = 0;
  for (int i = 0; i < 3; ++i) {
    const Rational d = exact[i] - Rational(point.value[i]);
    distance2 += d * d;
  }
  return distance2 <= Rational(point.error) * Rational(point.error);
}

Vector3 unit_direction(std::mt19937_64& engine) {
  std::normal_distribution<double> normal;
  const Vector3 v(normal(engine), normal(engine), normal(engine));
  return v / v.norm();
}

TEST(RoundedPoint, BoundsItsRoundingOnRandomBaseCentresOverTwelveDecades) {
  std::mt19937_64 engine(20261123);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-6.0, 6.0);
  for (int n = 0; n < 20000; ++n) {
    const double scale = std::pow(10.0, exponent(engine));
    const Vector3 minuend(unit(engine) * scale, unit(engine) * scale, unit(engine) * scale);
    const Vector3 subtrahend(unit(engine) * scale, unit(engine) * scale, unit(engine) * scale);
    const double length = std::fabs(unit(engine)) * scale + 1e-300;
    const int sign = n % 3 - 1;
    const RoundedPoint point = rounded_point(minuend, subtrahend, length, sign, unit_direction(engine));
    ASSERT_TRUE(error_holds(point)) << n;
  }
}

TEST(RoundedPoint, StaysRelativeToTheJointWhenTheJointIsFarFromTheOrigin) {
  // Journal and bearing 1e13 m from the origin, 1e-4 m apart: P_j - P_i is exact (Sterbenz),
  // and the bound is a few ulps of the joint's size, not of 1e13.
  const Vector3 bearing(1e13, -1e13, 1e13);
  const Vector3 journal = bearing + Vector3(1e-4, 0.0, -3e-5);
  const Vector3 axis = Vector3(0.01, 0.02, 1.0).normalized();
  const RoundedPoint point = rounded_point(journal, bearing, 0.0198, +1, axis);
  EXPECT_TRUE(error_holds(point));
  EXPECT_LT(point.error, 1e-17);
}

TEST(RoundedPoint, GivesAPositiveBoundEvenWhenTheSumHappensToBeExact) {
  // The bound is a priori: (1, 2, 4) + (2 / 2) (0, 0, 1) is computed exactly, and its bound is
  // still positive.
  const RoundedPoint rounded = rounded_point(Vector3(1.0, 2.0, 4.0), Vector3::Zero(), 2.0, +1, Vector3::UnitZ());
  EXPECT_EQ(rounded.value, Vector3(1.0, 2.0, 5.0));
  EXPECT_GT(rounded.error, 0.0);
  EXPECT_TRUE(error_holds(rounded));
}

TEST(RoundedPoint, BoundsSubnormalLengthsAndUnderflowingProducts) {
  const double tiny = 3 * 0x1p-1074;  // a subnormal length: halving it rounds
  const Vector3 direction = Vector3(1.0, 1e-10, 0.7).normalized();
  for (const double length : {tiny, 5 * 0x1p-1074, 0x1p-1060, 1e-310}) {
    for (const int sign : {-1, +1}) {
      const RoundedPoint point = rounded_point(Vector3(0x1p-1070, 0.0, -0x1p-1073), Vector3::Zero(), length,
                                               sign, direction);
      EXPECT_TRUE(error_holds(point)) << length;
    }
  }
}

TEST(RoundedPoint, BoundsHugeCoordinates) {
  const Vector3 direction = Vector3(0.3, -0.4, 0.5).normalized();
  const RoundedPoint point = rounded_point(Vector3(1e300, -3e299, 7e299), Vector3(-1e299, 2e300, 1e300),
                                           3e299, -1, direction);
  EXPECT_TRUE(std::isfinite(point.error));
  EXPECT_TRUE(error_holds(point));
}

TEST(RoundedPoint, ExactRationalPointFollowsTheKernelsPowerOfTwoRescaling) {
  const RoundedPoint point =
      rounded_point(Vector3(0.25, 1e-3, -7.0), Vector3(0.5, 0.0, 1e-8), 0.0198, +1, Vector3(0.0, 0.6, 0.8));
  const std::array<Rational, 3> unscaled = exact_rational_point(point, 0);
  for (const int e : {-900, -61, 61, 700, 1074}) {
    const std::array<Rational, 3> scaled = exact_rational_point(point, e);
    const Rational factor = e >= 0 ? Rational(std::ldexp(1.0, -e)) : Rational(1) / Rational(std::ldexp(1.0, e));
    for (int i = 0; i < 3; ++i) EXPECT_EQ(scaled[i], unscaled[i] * factor) << e;
  }
}

TEST(RoundedPoint, ScaledErrorRemainsABoundWhereItWouldUnderflow) {
  EXPECT_EQ(scaled_error(0.0, 500), 0.0);
  EXPECT_EQ(scaled_error(0x1p-20, 10), 0x1p-30 * (1 + 4 * kUnitRoundoff));
  EXPECT_GT(scaled_error(0x1p-1000, 500), 0.0);
  EXPECT_GE(scaled_error(0x1p-1000, 500), 0x1p-1022);
}

}  // namespace
}  // namespace clearjoint::geometry::detail
