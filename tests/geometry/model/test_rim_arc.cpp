// SPDX-License-Identifier: BSD-3-Clause
// RimArc: middle and sweep of counter-clockwise arcs on a rim, including arcs through angle 0.

#include "clearjoint/geometry/model/rim_arc.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

namespace clearjoint::geometry {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
/// middle() and sweep() add or subtract 2 pi and halve: a few roundings of quantities below
/// 4 pi, so 8 ulps of 4 pi bound the error.
constexpr double kAngleTolerance = 8 * std::numeric_limits<double>::epsilon() * 2 * kTwoPi;

TEST(RimArc, SweepOfAnArcNotThroughZeroIsEndMinusBegin) {
  const RimArc arc{1.0, 2.5, false};
  EXPECT_NEAR(arc.sweep(), 1.5, kAngleTolerance);
  EXPECT_NEAR(arc.middle(), 1.75, kAngleTolerance);
}

TEST(RimArc, SweepOfAnArcThroughZeroWrapsAround) {
  // From 5 rad counter-clockwise through 2 pi = 0 to 1 rad.
  const RimArc arc{5.0, 1.0, false};
  EXPECT_NEAR(arc.sweep(), 1.0 + kTwoPi - 5.0, kAngleTolerance);
  // Middle (5 + 1 + 2 pi) / 2 = 3 + pi, still below 2 pi.
  EXPECT_NEAR(arc.middle(), 3.0 + std::numbers::pi, kAngleTolerance);
}

TEST(RimArc, MiddleOfAnArcThroughZeroIsWrappedIntoRange) {
  // From 6 rad through 0 to 1 rad: the middle (7 + 2 pi) / 2 = 3.5 + pi is past 2 pi, so it wraps
  // to 3.5 - pi.
  const RimArc arc{6.0, 1.0, false};
  EXPECT_NEAR(arc.sweep(), 1.0 + kTwoPi - 6.0, kAngleTolerance);
  EXPECT_NEAR(arc.middle(), 3.5 - std::numbers::pi, kAngleTolerance);
  EXPECT_GE(arc.middle(), 0.0);
  EXPECT_LT(arc.middle(), kTwoPi);
}

TEST(RimArc, ArcEndingExactlyAtZeroHasItsMiddleBeforeTwoPi) {
  // Upper half of the range: from pi to 2 pi (stored as end 0 since angles are in [0, 2 pi)).
  const RimArc arc{std::numbers::pi, 0.0, false};
  EXPECT_NEAR(arc.sweep(), std::numbers::pi, kAngleTolerance);
  EXPECT_NEAR(arc.middle(), 1.5 * std::numbers::pi, kAngleTolerance);
}

TEST(RimArc, ArcStartingAtZeroIsNotMistakenForAWrap) {
  const RimArc arc{0.0, std::numbers::pi / 2, false};
  EXPECT_NEAR(arc.sweep(), std::numbers::pi / 2, kAngleTolerance);
  EXPECT_NEAR(arc.middle(), std::numbers::pi / 4, kAngleTolerance);
}

TEST(RimArc, FullRimSweepsTwoPiAndHasAMiddleInRange) {
  const RimArc arc{0.0, kTwoPi, true};
  EXPECT_NEAR(arc.sweep(), kTwoPi, kAngleTolerance);
  EXPECT_GE(arc.middle(), 0.0);
  EXPECT_LT(arc.middle(), kTwoPi);
}

TEST(RimArc, TinyArcAcrossZeroHasATinySweepAndAMiddleNearZero) {
  // The shape near-tangent penetration arcs take: a few ulps on each side of angle 0.
  const double begin = std::nextafter(kTwoPi, 0.0);
  const double end = 1e-15;
  const RimArc arc{begin, end, false};
  EXPECT_GE(arc.sweep(), 0.0);
  EXPECT_LT(arc.sweep(), 1e-14);
  const double m = arc.middle();
  EXPECT_TRUE(m < 1e-14 || m > kTwoPi - 1e-14) << m;
  EXPECT_LT(m, kTwoPi);
}

TEST(RimArc, SweepsOfComplementaryArcsAddUpToTwoPi) {
  for (double a : {0.0, 0.5, 2.0, 3.0, 6.0}) {
    for (double b : {0.25, 1.0, 4.0, 6.25}) {
      if (a == b) continue;
      const RimArc ab{a, b, false}, ba{b, a, false};
      EXPECT_NEAR(ab.sweep() + ba.sweep(), kTwoPi, kAngleTolerance) << a << " " << b;
      // The two middles are antipodal.
      const double gap = std::remainder(ab.middle() - ba.middle(), kTwoPi);
      EXPECT_NEAR(std::abs(gap), std::numbers::pi, kAngleTolerance) << a << " " << b;
    }
  }
}

}  // namespace
}  // namespace clearjoint::geometry
