// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/regularised_friction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {
namespace {

// The force is a product of a few correctly rounded operations (norm, tanh, scaling).
constexpr double kFewUlps = 8 * std::numeric_limits<double>::epsilon();

TEST(RegularisedFriction, HasCoulombMagnitudeTimesTanhAlongTheSlidingVelocity) {
  const FrictionParameters table2;  // mu = 0.1, k = 1000 s/m
  const Vector3 slip(3e-3, -4e-3, 0.0);  // |v_T| = 5 mm/s, k |v_T| = 5
  const Vector3 f = regularised_friction_force(table2, 200.0, slip);
  const double expected = 0.1 * 200.0 * std::tanh(5.0);  // eqs. (31)-(32)
  EXPECT_NEAR(f.norm(), expected, kFewUlps * expected);
  EXPECT_NEAR(f.normalized().dot(slip.normalized()), 1.0, kFewUlps);
}

TEST(RegularisedFriction, MatchesEquation32AtSeveralSpeedsCoefficientsAndDirections) {
  // Eq. (32) written out in long double with tanh x = -expm1(-2x) / (2 + expm1(-2x)) (exact
  // identity, a second formulation of tanh), against the library's vector, component by component.
  int compared = 0;
  for (const FrictionParameters p : {FrictionParameters{0.1, 1000.0}, FrictionParameters{0.35, 20.0}}) {
    for (const double normal_force : {3.0, 2.5e4}) {
      for (const double speed : {1e-7, 1e-4, 2e-3, 0.05, 3.0}) {
        for (const Vector3& direction : {Vector3(1, 0, 0), Vector3(0.36, -0.48, 0.8), Vector3(0, -0.6, -0.8)}) {
          const Vector3 slip = speed * direction;
          const long double x = static_cast<long double>(p.velocity_coefficient) * speed;
          const long double m = std::expm1(-2 * x);
          const long double magnitude = p.coefficient * static_cast<long double>(normal_force) * (-m / (2 + m));
          const Vector3 f = regularised_friction_force(p, normal_force, slip);
          for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(f[i], static_cast<double>(magnitude * direction[i]), kFewUlps * static_cast<double>(magnitude))
                << "mu " << p.coefficient << " k " << p.velocity_coefficient << " F " << normal_force << " v " << speed;
          }
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(compared, 2 * 2 * 5 * 3);
}

TEST(RegularisedFriction, NeverExceedsTheCoulombForce) {
  const FrictionParameters table2;
  for (double speed : {1e-6, 1e-3, 1.0, 1e3}) {
    EXPECT_LE(regularised_friction_force(table2, 10.0, Vector3(speed, 0, 0)).norm(), 0.1 * 10.0);
  }
}

TEST(RegularisedFriction, VanishesContinuouslyAtZeroSlip) {
  const FrictionParameters table2;
  EXPECT_EQ(regularised_friction_force(table2, 10.0, Vector3::Zero()), Vector3::Zero());
  // Near v_T = 0 eq. (32) is linear: mu F_N k v_T (tanh x = x - x^3/3: relative 3e-13 at x = 1e-6).
  const Vector3 slip(1e-9, 0.0, 0.0);
  const Vector3 f = regularised_friction_force(table2, 10.0, slip);
  EXPECT_NEAR(f.x() / (0.1 * 10.0 * 1000.0 * 1e-9), 1.0, 1e-12);
}

TEST(RegularisedFriction, IsZeroWithoutNormalForceOrCoefficient) {
  FrictionParameters p;
  EXPECT_EQ(regularised_friction_force(p, 0.0, Vector3(1, 0, 0)), Vector3::Zero());
  p.coefficient = 0.0;
  EXPECT_EQ(regularised_friction_force(p, 10.0, Vector3(1, 0, 0)), Vector3::Zero());
}

std::string validation_error(const FrictionParameters& p) {
  try {
    validate(p, "f");
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST(FrictionParameters, RejectBadValuesNamingTheField) {
  EXPECT_EQ(validation_error({}), "no error");
  EXPECT_EQ(validation_error({-0.1, 1000.0}), "f.coefficient = -0.10000000000000001: must be >= 0");
  EXPECT_EQ(validation_error({0.1, 0.0}), "f.velocity_coefficient = 0: must be positive");
  EXPECT_EQ(validation_error({std::numeric_limits<double>::infinity(), 1.0}),
            "f.coefficient = inf: must be finite");
}

}  // namespace
}  // namespace clearjoint::dynamics
