// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/model_builder.hpp"

#include <gtest/gtest.h>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/errors.hpp"
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
