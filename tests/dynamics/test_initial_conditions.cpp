// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/initial_conditions.hpp"

#include <gtest/gtest.h>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "dynamics_test_support.hpp"

namespace clearjoint::dynamics {
namespace {

using test::shipped_model;

// The corrector's own stopping tolerance (InitialConditionOptions defaults).
constexpr double kPositionTolerance = 1e-13;

TEST(InitialConditions, MoveAPerturbedSliderCrankOntoItsConstraints) {
  ModelDescription model = shipped_model("slider_crank_spatial_ideal.json");
  model.bodies[2].initial.position_W += Vector3(0.01, -0.004, 0.003);  // slider off its guide
  model.bodies[1].initial.euler_parameters += Vector4(0.02, -0.01, 0.0, 0.01);
  const BuiltModel built = build_model(model);
  EXPECT_GT(built.initial_conditions.iterations, 1);
  EXPECT_LE(built.initial_conditions.position_residual, kPositionTolerance);
  // The held crank did not move.
  EXPECT_EQ(built.initial_states[0].position_W, model.bodies[0].initial.position_W);
  EXPECT_NEAR(built.initial_states[0].angular_velocity_B.y(), 2 * M_PI, 1e-15);
  EXPECT_NEAR(built.initial_states[2].position_W.y(), 0.12, kPositionTolerance);
}

TEST(InitialConditions, GiveTheSliderCrankAtDeadCentreItsRodVelocity) {
  // Planar slider-crank at top dead centre: the slider is momentarily at rest and the rod turns at
  // -omega_crank L1/L2 = -75 rad/s.
  const BuiltModel built = build_model(shipped_model("slider_crank_planar_ideal.json"));
  EXPECT_NEAR(built.initial_states[2].velocity_W.norm(), 0.0, 1e-12);
  EXPECT_NEAR(built.initial_states[1].angular_velocity_B.z(), -75.0, 1e-12);
  EXPECT_NEAR(built.initial_states[1].angular_velocity_B.x(), 0.0, 1e-12);
}

TEST(InitialConditions, ReportContradictoryHeldVelocities) {
  ModelDescription model = shipped_model("slider_crank_planar_ideal.json");
  model.held_velocities.push_back({"slider", "vx", 3.0});  // at dead centre the slider is at rest
  EXPECT_THROW(build_model(model), SolverError);
}

TEST(InitialConditions, ReportConstraintsThatCannotBeMet) {
  ModelDescription model = shipped_model("slider_crank_planar_ideal.json");
  model.joints[1].point_j_B = Vector3(-1.0, 0.0, 0.0);  // rod "longer" than the guide allows
  model.held_positions.push_back({"slider", "x"});
  model.held_positions.push_back({"rod", "x"});
  try {
    build_model(model);
    FAIL() << "inconsistent constraints were accepted";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("initial positions"), std::string::npos) << e.what();
  }
}

TEST(InitialConditions, ReportUnmetConstraintsWhenEveryCoordinateIsHeld) {
  // Nothing may move, so the corrector has no column to solve for: a SolverError, not a crash in
  // the decomposition of a matrix without columns.
  ModelDescription model = shipped_model("slider_crank_planar_ideal.json");
  model.joints[1].point_j_B = Vector3(-1.0, 0.0, 0.0);
  model.held_positions.clear();
  for (const auto& body : model.bodies) {
    for (const char* component : {"x", "y", "z", "rx", "ry", "rz"}) {
      model.held_positions.push_back({body.properties.name, component});
    }
  }
  try {
    build_model(model);
    FAIL() << "inconsistent constraints were accepted";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("too many coordinates are held"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace clearjoint::dynamics
