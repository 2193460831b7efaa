// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/arithmetic/angles.hpp: wrap_angle maps every finite angle into [0, 2 pi).

#include "arithmetic/angles.hpp"

#include <gtest/gtest.h>

#include <boost/multiprecision/gmp.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "mpfr_reference.hpp"

namespace clearjoint::geometry::detail {
namespace {

using internal_testing::Real;
using Rational = boost::multiprecision::mpq_rational;

/// |kTwoPi - 2 pi|: kTwoPi is 2 pi rounded to double, below half an ulp of 2 pi (2^-51).
const double kTwoPiRounding = 0x1p-51;
/// Half an ulp of numbers in [4, 8): the rounding of the one addition of kTwoPi.
const double kHalfUlpOfTwoPi = 0x1p-51;

bool in_range(double a) { return a >= 0.0 && a < kTwoPi; }

/// Distance from `wrapped` to the true representative of `angle` modulo the real 2 pi.
Real distance_to_true_representative(double angle, double wrapped) {
  return internal_testing::circular_gap(Real(angle), Real(wrapped));
}

TEST(Angles, KeepsAnglesAlreadyInRangeUnchanged) {
  for (const double a : {0.0, 1e-300, 4.9e-324, 1.0, 3.0, 6.0, std::nextafter(kTwoPi, 0.0)}) {
    EXPECT_EQ(wrap_angle(a), a);
  }
}

TEST(Angles, MapsTwoPiAndItsMultiplesToZero) {
  EXPECT_EQ(wrap_angle(kTwoPi), 0.0);
  EXPECT_EQ(wrap_angle(-kTwoPi), 0.0);
  EXPECT_EQ(wrap_angle(2 * kTwoPi), 0.0);
  EXPECT_EQ(wrap_angle(-0.0), 0.0);
}

TEST(Angles, WrapsNegativeAnglesIntoRangeNextToTheirTrueRepresentative) {
  for (const double a : {-1.0, -3.0, -6.0, -7.0, -1e-17, -1e-300, -4.9e-324,
                         -std::nextafter(kTwoPi, 0.0), -std::nextafter(kTwoPi, 10.0), -20.0}) {
    const double w = wrap_angle(a);
    EXPECT_TRUE(in_range(w)) << a << " -> " << w;
    // One subtraction of kTwoPi (its distance to 2 pi) and one rounding per turn.
    const double turns = std::ceil(std::fabs(a) / kTwoPi) + 1;
    EXPECT_LE(distance_to_true_representative(a, w), Real(turns * kTwoPiRounding + kHalfUlpOfTwoPi))
        << a << " -> " << w;
  }
  // Negative angles within an ulp of 0 land on 0 or just below 2 pi, never on 2 pi itself.
  EXPECT_LT(wrap_angle(-1e-17), kTwoPi);
}

TEST(Angles, WrapsRandomModerateAnglesNextToTheirTrueRepresentative) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> angle(-100.0, 100.0);
  for (int i = 0; i < 5000; ++i) {
    const double a = angle(rng);
    const double w = wrap_angle(a);
    ASSERT_TRUE(in_range(w)) << a;
    // Reduction uses the double kTwoPi: each whole turn removed contributes its rounding.
    const double turns = std::ceil(std::fabs(a) / kTwoPi) + 1;
    ASSERT_LE(distance_to_true_representative(a, w), Real(turns * kTwoPiRounding + kHalfUlpOfTwoPi))
        << a;
  }
}

TEST(Angles, WrapsHugeAnglesIntoRangeCongruentModuloTheDoubleTwoPi) {
  // For |angle| >> 2 pi the result is the representative modulo the double kTwoPi (fmod is
  // exact), up to the rounding of one added kTwoPi; checked in exact rational arithmetic.
  std::vector<double> angles = {1e6, -1e6, 1e22, -1e22, 1e300, -1e300, 1.7976931348623157e308,
                                -1.7976931348623157e308, 0x1p60, -0x1p60};
  std::mt19937_64 rng(29);
  std::uniform_int_distribution<int> exponent(3, 1000);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) angles.push_back(std::ldexp(mantissa(rng), exponent(rng)));
  const Rational period(kTwoPi);
  for (const double a : angles) {
    const double w = wrap_angle(a);
    ASSERT_TRUE(in_range(w)) << a;
    const Rational turns = (Rational(a) - Rational(w)) / period;
    // Nearest integer number of turns: floor(turns + 1/2).
    const Rational shifted = turns + Rational(1, 2);
    const boost::multiprecision::mpz_int num = boost::multiprecision::numerator(shifted);
    const boost::multiprecision::mpz_int den = boost::multiprecision::denominator(shifted);
    boost::multiprecision::mpz_int n = num / den;  // truncates towards zero
    if (num < 0 && n * den != num) n -= 1;
    Rational residual = Rational(a) - Rational(w) - Rational(n) * period;
    if (residual < 0) residual = -residual;
    EXPECT_LE(residual, Rational(kHalfUlpOfTwoPi)) << a << " -> " << w;
  }
}

TEST(Angles, ApproximateAtan2StaysWithinItsErrorAllRound) {
  // Dense angles all round, at several radii, against libm (whose own error, ~1e-16, is far
  // below the bound), and the exact axes and diagonals.
  double worst = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const double angle = -std::numbers::pi + 2 * std::numbers::pi * i / 200000.0;
    for (const double radius : {1e-300, 1.0, 3e5, 1e300}) {
      const double x = radius * std::cos(angle), y = radius * std::sin(angle);
      worst = std::max(worst, std::fabs(approximate_atan2(y, x) - std::atan2(y, x)));
    }
  }
  EXPECT_LT(worst, kApproximateAngleError);
  EXPECT_GT(worst, 1e-8);  // the fit's error is real: the test would see a wrong polynomial
  for (const double x : {-2.0, 0.0, 2.0}) {
    for (const double y : {-2.0, 0.0, 2.0}) {
      EXPECT_NEAR(approximate_atan2(y, x), x == 0.0 && y == 0.0 ? 0.0 : std::atan2(y, x), kApproximateAngleError)
          << x << " " << y;
    }
  }
}

TEST(Angles, ApproximateAcosStaysWithinItsErrorAndClampsOutOfRangeCosines) {
  double worst = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const double c = -1.0 + 2.0 * i / 200000.0;
    worst = std::max(worst, std::fabs(approximate_acos(c) - std::acos(c)));
  }
  EXPECT_LT(worst, kApproximateAngleError);
  // Abramowitz and Stegun's bound for their 4.4.46 (2e-8) plus a few ulps of rounding; and the
  // fit's error is real: a wrong polynomial would show either way.
  const double kAbramowitzStegunError = 2e-8, kRoundingAllowance = 5e-9;
  EXPECT_LT(worst, kAbramowitzStegunError + kRoundingAllowance);
  EXPECT_GT(worst, 1e-9);
  EXPECT_NEAR(approximate_acos(1.0 + 1e-12), 0.0, kApproximateAngleError);
  EXPECT_NEAR(approximate_acos(-1.0 - 1e-12), std::numbers::pi, kApproximateAngleError);
}


/// The same double, bit for bit (a NaN matches any NaN).
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0 || (a != a && b != b); }

TEST(Angles, ApproximateAtan2InLanesGivesEachLaneTheScalarBits) {
  // Every octant and sign (the lane selects replace the scalar's branches), signed zeros, equal
  // magnitudes (the octant boundary), tiny and huge values, and random pairs; each lane against
  // the scalar call alone, with the other lane holding a different case.
  std::vector<double> values = {0.0, -0.0, 1.0, -1.0, 2.0, -2.0, 0.5, -0.5, 1e-300, -1e-300, 1e300, -1e300,
                                std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::infinity(),
                                -std::numeric_limits<double>::infinity()};
  std::mt19937_64 random(20261124);
  std::uniform_real_distribution<double> uniform(-3.0, 3.0);
  for (int i = 0; i < 200; ++i) values.push_back(uniform(random));
  int compared = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (std::size_t j = 0; j < values.size(); ++j) {
      const double y0 = values[i], x0 = values[j];
      const double y1 = values[(i + 7) % values.size()], x1 = values[(j + 3) % values.size()];
      const Pair lanes = approximate_atan2(Pair{y0, y1}, Pair{x0, x1});
      ASSERT_TRUE(same_bits(lanes[0], approximate_atan2(y0, x0))) << y0 << " " << x0;
      ASSERT_TRUE(same_bits(lanes[1], approximate_atan2(y1, x1))) << y1 << " " << x1;
      ++compared;
    }
  }
  EXPECT_EQ(compared, static_cast<int>(values.size() * values.size()));
}

TEST(Angles, ApproximateAtan2AndAcosGivesBothScalarAnglesBitForBit) {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> uniform(-3.0, 3.0), cosine(-1.2, 1.2);
  for (int i = 0; i < 20000; ++i) {
    const double y = uniform(random), x = uniform(random), c = cosine(random);
    const Pair both = approximate_atan2_and_acos(y, x, c);
    ASSERT_TRUE(same_bits(both[0], approximate_atan2(y, x))) << y << " " << x;
    ASSERT_TRUE(same_bits(both[1], approximate_acos(c))) << c;
  }
  for (const double c : {-1.0, 1.0, -0.0, 0.0, -1.5, 1.5}) {
    EXPECT_TRUE(same_bits(approximate_atan2_and_acos(0.0, 0.0, c)[1], approximate_acos(c))) << c;
    EXPECT_TRUE(same_bits(approximate_atan2_and_acos(0.0, 0.0, c)[0], 0.0));
  }
}

}  // namespace
}  // namespace clearjoint::geometry::detail
