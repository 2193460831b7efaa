// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/normal_contact_force.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "clearjoint/dynamics/errors.hpp"
#include "one_dimensional_impact.hpp"

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

/// F_N of each law written out from its source, in long double: K delta^n (1 + chi delta_dot / K)
/// with chi delta_dot(-) / K = 3 (1 - ce^2) / 4 (Lankarani-Nikravesh, eq. 28), 3 (1 - ce) / 2
/// (Hunt-Crossley), 8 (1 - ce) / (5 ce) (Flores et al. 2011), 0 (Hertz); never negative.
long double closed_form_force(NormalForceModel model, long double K, long double n, long double ce,
                              long double depth, long double speed, long double impact_speed) {
  long double factor = 0;
  if (model == NormalForceModel::lankarani_nikravesh) factor = 3 * (1 - ce * ce) / 4;
  if (model == NormalForceModel::hunt_crossley) factor = 3 * (1 - ce) / 2;
  if (model == NormalForceModel::flores) factor = 8 * (1 - ce) / (5 * ce);
  const long double force = K * std::pow(depth, n) * (1 + factor * speed / impact_speed);
  return force > 0 ? force : 0;
}

TEST(NormalContactForce, EveryLawMatchesItsClosedFormAtSeveralDepthsSpeedsAndRestitutions) {
  // Rounding: delta^n (an ulp or two), the factor and the product: a few ulps of the elastic
  // force times the largest term of (1 + factor speed / impact speed).
  int compared = 0;
  for (NormalForceModel m : {NormalForceModel::hertz, NormalForceModel::lankarani_nikravesh,
                             NormalForceModel::hunt_crossley, NormalForceModel::flores}) {
    for (const double ce : {0.3, 0.9, 1.0}) {
      for (const double exponent : {1.5, 1.0, 2.2}) {
        NormalForceParameters p = law(m, ce);
        p.exponent = exponent;
        p.stiffness = 3.7e10;
        for (const double depth : {1e-9, 4e-7, 2.5e-5}) {
          for (const double speed : {0.8, 0.05, 0.0, -0.02, -0.3}) {
            const double impact_speed = 0.4;
            const long double expected =
                closed_form_force(m, p.stiffness, exponent, ce, depth, speed, impact_speed);
            const double scale = p.stiffness * std::pow(depth, exponent) *
                                 (1 + std::abs(hysteresis_factor(p) * speed / impact_speed));
            EXPECT_NEAR(normal_contact_force(p, depth, speed, impact_speed), static_cast<double>(expected),
                        kFewUlps * scale)
                << to_string(m) << " ce " << ce << " n " << exponent << " depth " << depth << " speed " << speed;
            ++compared;
          }
        }
      }
    }
  }
  EXPECT_EQ(compared, 4 * 3 * 3 * 3 * 5);
}

TEST(NormalContactForce, EachLawGivesItsClosedFormRestitutionInASingleImpact) {
  // The 1-D impact integrated at 1e-14 against G(1) = G(-e) (one_dimensional_impact.hpp): they
  // agree to 2e-12 in every case here (measured 2.7e-13 .. 1.95e-12: the integrator's error
  // over the ~100 steps of the impact). 1e-9 leaves a margin of 500 and still sees a change of
  // the law's factor in its fourth digit (de/da ~ -0.6).
  constexpr double kIntegratedRestitutionTolerance = 1e-9;
  for (NormalForceModel m : {NormalForceModel::hertz, NormalForceModel::lankarani_nikravesh,
                             NormalForceModel::hunt_crossley, NormalForceModel::flores}) {
    for (const double ce : {0.5, 0.9, 0.99}) {
      const NormalForceParameters p = law(m, ce);
      const double e = test::integrated_restitution(p, 1.0, 0.1);
      EXPECT_NEAR(e, test::closed_form_restitution(hysteresis_factor(p)), kIntegratedRestitutionTolerance)
          << to_string(m) << " ce " << ce;
    }
  }
}

TEST(NormalContactForce, EachLawGivesTheRestitutionItWasChosenForWithinItsKnownError) {
  // What each law promises: Hertz is elastic (e = 1 whatever ce); Lankarani-Nikravesh and
  // Hunt-Crossley give e = ce to first order in 1 - ce (both are derived for ce near 1); Flores et
  // al. (2011) is derived for the whole range. The restitution each actually gives (the 1-D
  // impact above, equal to the closed form to 1e-9), e - ce:
  //   ce        0.99       0.9       0.5
  //   L-N     +0.00015  +0.0132   +0.225
  //   H-C     +0.00010  +0.0090   +0.163
  //   Flores  -0.00066  -0.0061   -0.030
  // The bounds below are those figures plus ~20 %: each law's error against its own promise,
  // written down. (The previous test is the one that sees a wrong coefficient: it moves e by
  // ~0.6 times the change of the factor.) And what makes Flores the law for low restitution: at
  // ce = 0.5 the first-order laws miss by more than 0.15.
  struct Promise {
    NormalForceModel model;
    double ce;
    double bound;
  };
  const Promise promises[] = {
      {NormalForceModel::lankarani_nikravesh, 0.99, 0.0002}, {NormalForceModel::lankarani_nikravesh, 0.9, 0.016},
      {NormalForceModel::lankarani_nikravesh, 0.5, 0.27},    {NormalForceModel::hunt_crossley, 0.99, 0.00012},
      {NormalForceModel::hunt_crossley, 0.9, 0.011},         {NormalForceModel::hunt_crossley, 0.5, 0.2},
      {NormalForceModel::flores, 0.99, 0.0008},              {NormalForceModel::flores, 0.9, 0.0073},
      {NormalForceModel::flores, 0.5, 0.036},
  };
  for (const Promise& p : promises) {
    const double e = test::integrated_restitution(law(p.model, p.ce), 1.0, 0.1);
    EXPECT_NEAR(e, p.ce, p.bound) << to_string(p.model) << " ce " << p.ce;
    if (p.ce == 0.5 && p.model != NormalForceModel::flores) {
      EXPECT_GT(e - p.ce, 0.15) << to_string(p.model);
    }
  }
  constexpr double kIntegratedRestitutionTolerance = 1e-9;  // as in the previous test
  EXPECT_NEAR(test::integrated_restitution(law(NormalForceModel::hertz, 0.5), 1.0, 0.1), 1.0,
              kIntegratedRestitutionTolerance);
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
