// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/normal_contact_force.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {
namespace {

// delta sqrt(delta) and pow(delta, 1.5) are each correctly rounded or within an ulp or two of
// the real value; their difference is a few ulps.
constexpr double kFewUlps = 8 * std::numeric_limits<double>::epsilon();

NormalForceParameters law(NormalForceModel model, double restitution = 0.9) {
  NormalForceParameters p;
  p.model = model;
  p.restitution = restitution;
  return p;
}

TEST(NormalContactForce, HertzIsKTimesDepthToTheExponentWhateverTheSpeed) {
  const NormalForceParameters hertz = law(NormalForceModel::hertz);
  for (double depth : {1e-9, 3e-7, 2e-5}) {
    const double expected = 1e11 * std::pow(depth, 1.5);
    for (double speed : {-0.3, 0.0, 0.7}) {
      EXPECT_NEAR(normal_contact_force(hertz, depth, speed, 0.5), expected, kFewUlps * expected);
    }
  }
}

TEST(NormalContactForce, RaisesAZeroOrMissingImpactSpeedToTheFloorInsteadOfReturningNothing) {
  // An impact speed of 0 used to make 0 / 0 in the damping term: a NaN force, clamped to 0.
  NormalForceParameters hertz;
  hertz.model = NormalForceModel::hertz;
  hertz.stiffness = 4.0;
  EXPECT_EQ(normal_contact_force(hertz, 0.25, 0.0, 0.0), 0.5);  // 4 * 0.25^1.5, exact
  NormalForceParameters ln;  // Lankarani-Nikravesh: the floor stands in for the impact speed
  const double at_floor = normal_contact_force(ln, 1e-6, 0.5, ln.minimum_impact_speed);
  EXPECT_EQ(normal_contact_force(ln, 1e-6, 0.5, 0.0), at_floor);
  EXPECT_EQ(normal_contact_force(ln, 1e-6, 0.5, std::nan("")), at_floor);
  EXPECT_GT(at_floor, normal_contact_force(ln, 1e-6, 0.0, 1.0));
}

TEST(NormalContactForce, UsesTheGivenExponent) {
  NormalForceParameters linear = law(NormalForceModel::hertz);
  linear.exponent = 1.0;
  EXPECT_DOUBLE_EQ(normal_contact_force(linear, 2e-6, 0.0, 1.0), 1e11 * 2e-6);
}

TEST(NormalContactForce, IsZeroWithoutPenetration) {
  for (NormalForceModel m : {NormalForceModel::hertz, NormalForceModel::lankarani_nikravesh,
                             NormalForceModel::hunt_crossley, NormalForceModel::flores}) {
    EXPECT_EQ(normal_contact_force(law(m), 0.0, 1.0, 1.0), 0.0);
    EXPECT_EQ(normal_contact_force(law(m), -1e-6, 1.0, 1.0), 0.0);
    EXPECT_EQ(contact_elastic_energy(law(m), -1e-6), 0.0);
  }
}

TEST(NormalContactForce, LankaraniNikravesh_AddsThreeQuartersOfOneMinusCeSquaredAtTheImpactSpeed) {
  const NormalForceParameters ln = law(NormalForceModel::lankarani_nikravesh, 0.9);
  const double depth = 1e-6, elastic = 1e11 * std::pow(depth, 1.5);
  // eq. (29) at delta_dot = delta_dot(-): 1 + 3 (1 - 0.81) / 4 = 1.1425
  EXPECT_NEAR(normal_contact_force(ln, depth, 0.2, 0.2), 1.1425 * elastic, kFewUlps * elastic);
  // at the deepest point (delta_dot = 0) only the elastic part remains
  EXPECT_NEAR(normal_contact_force(ln, depth, 0.0, 0.2), elastic, kFewUlps * elastic);
  // restitution: less than elastic
  EXPECT_NEAR(normal_contact_force(ln, depth, -0.1, 0.2), (1 - 0.1425 / 2) * elastic, kFewUlps * elastic);
}

TEST(NormalContactForce, HysteresisFactorsFollowEachLaw) {
  EXPECT_EQ(hysteresis_factor(law(NormalForceModel::hertz, 0.5)), 0.0);
  EXPECT_DOUBLE_EQ(hysteresis_factor(law(NormalForceModel::lankarani_nikravesh, 0.5)), 0.75 * 0.75);
  EXPECT_DOUBLE_EQ(hysteresis_factor(law(NormalForceModel::hunt_crossley, 0.5)), 0.75);
  EXPECT_DOUBLE_EQ(hysteresis_factor(law(NormalForceModel::flores, 0.5)), 8.0 * 0.5 / (5.0 * 0.5));
}

TEST(NormalContactForce, EveryDampedLawIsElasticAtRestitutionOne) {
  for (NormalForceModel m : {NormalForceModel::lankarani_nikravesh, NormalForceModel::hunt_crossley,
                             NormalForceModel::flores}) {
    EXPECT_EQ(hysteresis_factor(law(m, 1.0)), 0.0) << to_string(m);
  }
}

TEST(NormalContactForce, NeverPullsTheBodiesTogether) {
  // Flores at ce = 0.2: factor 8 (0.8) / (5 (0.2)) = 6.4; separating at more than 1/6.4 of the
  // impact speed the law would pull.
  const NormalForceParameters flores = law(NormalForceModel::flores, 0.2);
  EXPECT_EQ(normal_contact_force(flores, 1e-6, -0.1, 0.5), 0.0);   // 1 - 6.4 (0.2) < 0
  EXPECT_GT(normal_contact_force(flores, 1e-6, -0.05, 0.5), 0.0);  // 1 - 6.4 (0.1) > 0
}

TEST(NormalContactForce, ElasticEnergyIsTheIntegralOfTheElasticForce) {
  const NormalForceParameters hertz = law(NormalForceModel::hertz);
  // Central difference of K delta^2.5 / 2.5 with h = 1e-4 delta: truncation (h^2/6) U''' relative
  // ~ 1e-9, rounding eps U / h ~ 1e-12 relative.
  constexpr double kCentralDifferenceTolerance = 1e-8;
  for (double depth : {1e-7, 5e-6}) {
    const double h = 1e-4 * depth;
    const double derivative =
        (contact_elastic_energy(hertz, depth + h) - contact_elastic_energy(hertz, depth - h)) / (2 * h);
    const double force = normal_contact_force(hertz, depth, 0.0, 1.0);
    EXPECT_NEAR(derivative / force, 1.0, kCentralDifferenceTolerance);
  }
}

TEST(NormalForceModelNames, RoundTripAndRejectUnknownNamesNamingTheField) {
  for (NormalForceModel m : {NormalForceModel::hertz, NormalForceModel::lankarani_nikravesh,
                             NormalForceModel::hunt_crossley, NormalForceModel::flores}) {
    EXPECT_EQ(normal_force_model_from_string(to_string(m), "f"), m);
  }
  try {
    normal_force_model_from_string("kelvin_voigt", "forces[0].normal_force.model");
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("forces[0].normal_force.model = \"kelvin_voigt\""),
              std::string::npos) << e.what();
  }
}

std::string validation_error(const NormalForceParameters& p) {
  try {
    validate(p, "n");
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST(NormalForceParameters, RejectBadValuesNamingTheField) {
  NormalForceParameters p;
  EXPECT_EQ(validation_error(p), "no error");
  p.stiffness = 0.0;
  EXPECT_EQ(validation_error(p), "n.stiffness = 0: must be positive");
  p = {};
  p.exponent = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(validation_error(p), "n.exponent = nan: must be finite");
  p = {};
  p.restitution = 1.5;
  EXPECT_EQ(validation_error(p), "n.restitution = 1.5: must lie in [0, 1]");
  p = law(NormalForceModel::flores, 0.0);
  EXPECT_EQ(validation_error(p), "n.restitution = 0: must lie in (0, 1] for the flores model");
  p = {};
  p.minimum_impact_speed = -1e-3;
  EXPECT_EQ(validation_error(p), "n.minimum_impact_speed = -0.001: must be positive");
}

}  // namespace
}  // namespace clearjoint::dynamics
