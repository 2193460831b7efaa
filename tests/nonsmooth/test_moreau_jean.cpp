// SPDX-License-Identifier: BSD-3-Clause
// The Moreau-Jean integrator on a journal falling freely in a bearing fixed to the ground: one
// impact, whose energy balance and Newton law are known exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/dynamics/simulator.hpp"
#include "clearjoint/nonsmooth/moreau_jean.hpp"

namespace clearjoint::nonsmooth {
namespace {

constexpr double kMass = 0.5;
constexpr double kGravity = 9.81;
constexpr double kDropSpeed = 0.5;  // [m/s] downwards, at the start, journal centred

/// A journal (0.5 kg) centred in a bearing on the ground (paper Table 2 dimensions: 0.1 mm
/// clearances), moving down at 0.5 m/s under gravity: it hits the wall after about 0.2 ms.
std::string falling_journal(double restitution, double friction, const std::string& solver) {
  return R"({"name": "falling journal", "gravity": [0, -9.81, 0],
    "bodies": [{"name": "journal", "mass": 0.5, "inertia": [1e-4, 1e-4, 2e-5],
                "position": [0, 0, 0], "velocity": [0, -0.5, 0]}],
    "forces": [{"type": "clearance_revolute", "name": "joint",
      "bearing": {"body": "ground", "point": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.01, "length": 0.02},
      "journal": {"body": "journal", "point": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.0099, "length": 0.0198},
      "normal_force": {"model": "hertz", "stiffness": 1e11, "exponent": 1.5, "restitution": )" +
         std::to_string(restitution) + R"(},
      "friction": {"coefficient": )" + std::to_string(friction) + R"(}}],
    "solver": )" + solver + "}";
}

struct Impact {
  double energy_before = 0.0;
  double energy_after = 0.0;
  double normal_velocity_before = 0.0;
  double normal_velocity_after = 0.0;
  int steps_with_percussion = 0;
};

/// Steps until the first contact's impact is over (the journal moves up again), recording the
/// energy at the start of the first step with a percussion and at the end of the last.
Impact first_impact(double restitution, double step) {
  const auto model = dynamics::parse_model(
      falling_journal(restitution, 0.0, R"({"method": "moreau_jean", "step": )" + std::to_string(step) + "}"),
      "test");
  MoreauJean scheme(model);
  Impact impact;
  for (int k = 0; k < 100000 && scheme.time() < 2e-3; ++k) {
    const double energy = scheme.kinetic_energy() + scheme.potential_energy();
    scheme.step();
    bool percussion = false;
    for (const ContactPercussion& c : scheme.contacts()) {
      if (c.normal_percussion > 0.0) {
        percussion = true;
        if (impact.steps_with_percussion == 0) {
          impact.energy_before = energy;
          impact.normal_velocity_before = c.normal_velocity_before;
        }
        impact.normal_velocity_after = c.normal_velocity_after;
      }
    }
    if (percussion) {
      ++impact.steps_with_percussion;
      impact.energy_after = scheme.kinetic_energy() + scheme.potential_energy();
    } else if (impact.steps_with_percussion > 0 && restitution > 0.0) {
      break;
    } else if (impact.steps_with_percussion > 0) {
      break;
    }
  }
  return impact;
}

TEST(MoreauJean, KeepsTheEnergyOfAnElasticImpactToOrderH) {
  for (double h : {1e-5, 1e-6}) {
    const Impact impact = first_impact(1.0, h);
    ASSERT_GT(impact.steps_with_percussion, 0) << "h = " << h;
    // The impact happens anywhere within the activation test's half step of the wall, so the
    // journal's height, and its potential energy, can differ by gravity times one step's travel.
    const double order_h = kMass * kGravity * h * (kDropSpeed + kGravity * 1e-3);
    EXPECT_NEAR(impact.energy_after, impact.energy_before, order_h) << "h = " << h;
    EXPECT_NEAR(impact.normal_velocity_after, -impact.normal_velocity_before, 1e-8) << "h = " << h;
  }
}

TEST(MoreauJean, StopsTheNormalVelocityInAPlasticImpact) {
  const Impact impact = first_impact(0.0, 1e-5);
  ASSERT_GT(impact.steps_with_percussion, 0);
  EXPECT_LT(impact.normal_velocity_before, -0.4);
  EXPECT_NEAR(impact.normal_velocity_after, 0.0, 1e-9);
}

TEST(MoreauJean, FallsFreelyBeforeTheContact) {
  const auto model = dynamics::parse_model(falling_journal(1.0, 0.0, R"({"method": "moreau_jean", "step": 1e-5})"), "test");
  MoreauJean scheme(model);
  for (int k = 0; k < 10; ++k) scheme.step();
  EXPECT_TRUE(scheme.contacts().empty());
  const double t = scheme.time();
  // State: [x y z e0..e3 | vx vy vz ...]; theta = 1/2 integrates constant gravity exactly.
  EXPECT_NEAR(scheme.state()[1], -kDropSpeed * t - 0.5 * kGravity * t * t, 1e-15);
  EXPECT_NEAR(scheme.state()[8], -kDropSpeed - kGravity * t, 1e-14);
}

TEST(MoreauJean, ReportsTheTimeOfStepKAsStartPlusKStepsWithoutAccumulatingRounding) {
  // 5000 steps of 1e-5 s: summing h drifts by about one rounding a step (5e-17 s each); the
  // time column of a run must read start + k h as the fixed-step scheme defines it.
  const auto model = dynamics::parse_model(
      falling_journal(1.0, 0.0, R"({"method": "moreau_jean", "step": 1e-5, "start_time": 0.125})"), "test");
  MoreauJean scheme(model);
  for (int k = 1; k <= 5000; ++k) {
    scheme.step();
    ASSERT_EQ(scheme.time(), 0.125 + k * 1e-5) << "after step " << k;
  }
}

TEST(MoreauJean, RefusesAModelFileStepThatIsNotPositive) {
  for (const char* step : {"0", "-1e-5", "1e300"}) {
    try {
      dynamics::parse_model(falling_journal(1.0, 0.0, std::string(R"({"method": "moreau_jean", "step": )") + step + "}"), "m.json");
      ADD_FAILURE() << "accepted step " << step;
    } catch (const dynamics::ModelError& e) {
      EXPECT_NE(std::string(e.what()).find("solver.step = "), std::string::npos) << e.what();
    }
  }
}

TEST(MoreauJean, RefusesAThetaOutsideHalfToOne) {
  try {
    dynamics::parse_model(falling_journal(1.0, 0.0, R"({"method": "moreau_jean", "theta": 0.3})"), "m.json");
    ADD_FAILURE() << "accepted theta 0.3";
  } catch (const dynamics::ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("solver.theta = 0.3: must be in [0.5, 1]"), std::string::npos) << e.what();
  }
}

TEST(MoreauJean, RefusesAnUnknownSolverMethodNamingTheField) {
  try {
    dynamics::parse_model(falling_journal(1.0, 0.0, R"({"method": "moreau"})"), "m.json");
    ADD_FAILURE() << "accepted method moreau";
  } catch (const dynamics::ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("solver.method = \"moreau\": unknown solver method"), std::string::npos)
        << e.what();
  }
}

TEST(MoreauJean, RefusesAStepWithoutTheMoreauJeanMethod) {
  try {
    dynamics::parse_model(falling_journal(1.0, 0.0, R"({"step": 1e-5})"), "m.json");
    ADD_FAILURE() << "accepted a step for the compliant integrator";
  } catch (const dynamics::ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("solver.step: only read with"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace clearjoint::nonsmooth

namespace clearjoint::nonsmooth {
namespace {

TEST(MoreauJean, RefusesALubricatedJointNamingTheField) {
  // Rigid contact has no film (docs/nonsmooth.md, "What it assumes").
  dynamics::ModelDescription model =
      dynamics::read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/slider_crank_planar_clearance_lubricated.json");
  model.solver_method = dynamics::SolverMethod::moreau_jean;
  try {
    MoreauJean scheme(model);
    ADD_FAILURE() << "ran a lubricated joint without its film";
  } catch (const dynamics::ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("forces[0].lubrication: a lubricated joint is not supported by "
                                         "solver.method = \"moreau_jean\""),
              std::string::npos)
        << e.what();
  }
}

TEST(MoreauJean, KeepsTheSpatialSliderCranksIdealJointsAssembledThroughItsImpacts) {
  // The position projection solves with the step's factor of Phi_q M^-1 Phi_q^T (a chord
  // method): it must still bring every step's drift below its tolerance (1e-12, moreau_jean.cpp),
  // here through the first 0.1 s of the paper's Section 6.2 mechanism, impacts included.
  dynamics::ModelDescription model =
      dynamics::read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/slider_crank_spatial_clearance.json");
  model.solver_method = dynamics::SolverMethod::moreau_jean;
  model.moreau_jean.step = 1e-4;
  MoreauJean scheme(model);
  long steps_with_contacts = 0;
  for (int k = 0; k < 1000; ++k) {
    scheme.step();
    if (!scheme.contacts().empty()) ++steps_with_contacts;
  }
  EXPECT_GT(steps_with_contacts, 0);
  EXPECT_LE(scheme.statistics().largest_projection_residual, 1e-12);
  EXPECT_GT(scheme.statistics().largest_projection_residual, 0.0);  // the projection had work to do
}

TEST(MoreauJean, SolvesEveryContactProblemOfTheMisalignedPlanarSliderCranksRimContacts) {
  // From t = 0.0141 s the misaligned journal touches the bearing at both rims with nearly the
  // same normal: W_NN's off-diagonal term is 0.992 of its diagonal ones, so Gauss-Seidel gains
  // a factor 0.985 per sweep and fc3d NSGS needs some 1250 sweeps where 1000 are allowed. The
  // fallback to fc3d PROX (contact_problem.cpp) must bring every step to the tolerance.
  dynamics::ModelDescription model =
      dynamics::read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/slider_crank_planar_clearance_misaligned.json");
  model.solver_method = dynamics::SolverMethod::moreau_jean;
  MoreauJean scheme(model);
  ASSERT_EQ(model.moreau_jean.step, 1e-5);  // the default step, at which the rim contacts start at 0.0141 s
  for (int k = 0; k < 1500; ++k) scheme.step();
  const MoreauJeanStatistics& statistics = scheme.statistics();
  EXPECT_EQ(statistics.unconverged_steps, 0) << "the first at t = " << statistics.first_unconverged_time << " s";
  EXPECT_LE(statistics.largest_solver_error, model.moreau_jean.contact_tolerance);
  EXPECT_GT(statistics.fallback_solves, 0);  // NSGS alone missed some: the fallback had work to do
}

TEST(MoreauJean, IsNeverRunByTheCompliantIntegrator) {
  const auto model = dynamics::parse_model(falling_journal(1.0, 0.0, R"({"method": "moreau_jean"})"), "m.json");
  try {
    dynamics::Simulator simulator(model);
    ADD_FAILURE() << "the compliant integrator accepted a moreau_jean model";
  } catch (const dynamics::ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("solver.method = \"moreau_jean\": run by clearjoint::nonsmooth"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace clearjoint::nonsmooth
