// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/model_builder.hpp"

#include <gtest/gtest.h>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/model_file.hpp"
#include "dynamics_test_support.hpp"

namespace clearjoint::dynamics {
namespace {

std::string error_of(const ModelDescription& model) {
  try {
    build_model(model);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

std::string start_error_of(const ModelDescription& model) {
  try {
    consistent_start(model);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

TEST(ModelBuilder, NamesAnUnknownBodyInAJoint) {
  ModelDescription model = test::pendulum_model({});
  model.joints[0].body_j = "bobb";
  EXPECT_EQ(error_of(model),
            "joints[0].body_j = \"bobb\": no body of that name (use \"ground\" for the world frame)");
}

TEST(ModelBuilder, RejectsDuplicateBodyNames) {
  ModelDescription model = test::pendulum_model({});
  model.bodies.push_back(model.bodies[0]);
  EXPECT_EQ(error_of(model), "bodies[1].name = \"bob\": used by bodies[0] already");
}

TEST(ModelBuilder, RejectsAnInfiniteInitialPosition) {
  ModelDescription model = test::pendulum_model({});
  model.bodies[0].initial.position_W.x() = INFINITY;
  const std::string message = error_of(model);
  EXPECT_EQ(message.rfind("bodies[0].position = [inf, ", 0), 0u) << message;
  EXPECT_NE(message.find("]: must be finite"), std::string::npos) << message;
}

TEST(ModelBuilder, RejectsUnknownHeldComponents) {
  ModelDescription model = test::pendulum_model({});
  model.held_positions.push_back({"bob", "theta"});
  EXPECT_EQ(error_of(model),
            "initial_conditions.hold_positions[0].components = \"theta\": must be one of x, y, z, rx, ry, rz");
}

/// The pendulum with a clearance joint between its bob (journal) and the ground (bearing).
ModelDescription pendulum_with_clearance_joint() {
  ModelDescription model = test::pendulum_model({});
  model.forces.push_back(ClearanceRevoluteDescription{
      "gap", {"ground", Vector3::Zero(), Vector3::UnitZ()}, {"bob", Vector3(0, 0.5, 0), Vector3::UnitZ()}, {}});
  return model;
}

TEST(ModelBuilder, BuildsAClearanceJointAfterGravityWithItsImpactMemory) {
  BuiltModel built = build_model(pendulum_with_clearance_joint());
  ASSERT_EQ(built.system->force_elements().size(), 2u);
  EXPECT_EQ(built.system->force_elements()[1]->name(), "gap");
  EXPECT_EQ(built.system->layout().extra_count, kContactSlotCount);
}

TEST(ModelBuilder, NamesAnUnknownBodyOfAClearanceJoint) {
  ModelDescription model = pendulum_with_clearance_joint();
  std::get<ClearanceRevoluteDescription>(model.forces[0]).journal.body = "bobb";
  EXPECT_EQ(error_of(model), "forces[0].journal.body = \"bobb\": no body of that name (use \"ground\" "
                             "for the world frame)");
}

TEST(ModelBuilder, NamesAnUnknownForceElementAmongTheOutputs) {
  ModelDescription model = pendulum_with_clearance_joint();
  model.output_all_force_elements = false;
  model.output_force_elements = {"gap", "gapp"};
  EXPECT_EQ(error_of(model), "output.force_elements[1] = \"gapp\": no force element of that name");
}

/// The lubricated slider-crank (its joint builds an oil film) with one more force: a spring whose
/// constructor refuses its negative stiffness, so that building the force elements throws.
ModelDescription lubricated_slider_crank_with_unbuildable_spring() {
  ModelDescription model = read_model_file(std::string(CLEARJOINT_MODELS_DIR) +
                                           "/slider_crank_planar_clearance_lubricated.json");
  SpringDamperDescription spring{"unbuildable", "rod", "slider", Vector3::Zero(), Vector3::Zero(), {}};
  spring.parameters.stiffness = -1.0;
  model.forces.push_back(spring);
  return model;
}

TEST(ConsistentStart, GivesBuildModelsInitialStatesWithoutBuildingAnyForceElement) {
  ModelDescription model = lubricated_slider_crank_with_unbuildable_spring();
  EXPECT_THROW(build_model(model), ModelError);
  const ConsistentStart start = consistent_start(model);
  model.forces.pop_back();
  const BuiltModel built = build_model(model);
  ASSERT_EQ(start.initial_states.size(), built.initial_states.size());
  for (size_t b = 0; b < start.initial_states.size(); ++b) {
    const BodyState& s = start.initial_states[b];
    const BodyState& expected = built.initial_states[b];
    EXPECT_TRUE(s.position_W == expected.position_W) << b;  // bit for bit
    EXPECT_TRUE(s.euler_parameters == expected.euler_parameters) << b;
    EXPECT_TRUE(s.velocity_W == expected.velocity_W) << b;
    EXPECT_TRUE(s.angular_velocity_B == expected.angular_velocity_B) << b;
  }
  EXPECT_EQ(start.initial_conditions.iterations, built.initial_conditions.iterations);
  EXPECT_EQ(start.initial_conditions.position_residual, built.initial_conditions.position_residual);
  EXPECT_EQ(start.initial_conditions.velocity_residual, built.initial_conditions.velocity_residual);
}

TEST(ConsistentStart, NamesAnUnknownBodyOfAForceAndAnUnknownForceAmongTheOutputs) {
  ModelDescription model = pendulum_with_clearance_joint();
  std::get<ClearanceRevoluteDescription>(model.forces[0]).journal.body = "bobb";
  EXPECT_EQ(start_error_of(model), "forces[0].journal.body = \"bobb\": no body of that name (use \"ground\" "
                                   "for the world frame)");
  model = pendulum_with_clearance_joint();
  model.output_all_force_elements = false;
  model.output_force_elements = {"gap", "gravity", "gapp"};
  EXPECT_EQ(start_error_of(model), "output.force_elements[2] = \"gapp\": no force element of that name");
}

TEST(ModelBuilder, AddsGravityAsAForceElementWithPotentialEnergy) {
  BuiltModel built = build_model(test::pendulum_model({}));
  ASSERT_EQ(built.system->force_elements().size(), 1u);
  EXPECT_EQ(built.system->force_elements()[0]->name(), "gravity");
  // -m g . r with g = (0, -9.81, 0) and r_y = -L cos(theta0): the bob hangs below the datum.
  EXPECT_NEAR(built.system->potential_energy(0.0, built.initial_state),
              -1.0 * test::kStandardGravity * 0.5 * std::cos(0.01), 1e-14);
}

}  // namespace
}  // namespace clearjoint::dynamics
