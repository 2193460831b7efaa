// SPDX-License-Identifier: BSD-3-Clause
// model_description.hpp is plain data: it reaches the parameter structs of the joint, the force
// laws and the integrator through headers of their own, and no equations, integrator, force
// element or kernel query. The compiler checks it: after the description alone, each name below
// is still free, so declaring it as something else compiles; were the integrator (say) pulled in
// again, `using Integrator = ...` would clash with its class and this file would not build.

#include "clearjoint/dynamics/model_description.hpp"

#include <gtest/gtest.h>

#include <type_traits>

namespace clearjoint::dynamics {
struct NotDeclaredByTheDescription {};
// The integrator and what it integrates.
using Integrator = NotDeclaredByTheDescription;
using MultibodySystem = NotDeclaredByTheDescription;
using ConstraintSet = NotDeclaredByTheDescription;
using InitialConditionReport = NotDeclaredByTheDescription;
// The force elements and their evaluation.
using ForceElement = NotDeclaredByTheDescription;
using ClearanceRevoluteJoint = NotDeclaredByTheDescription;
using SpringDamper = NotDeclaredByTheDescription;
using ConstraintRows = NotDeclaredByTheDescription;
using SystemKinematics = NotDeclaredByTheDescription;
}  // namespace clearjoint::dynamics

namespace clearjoint::geometry {
// The kernel: its detection and its queries.
using JointContacts = dynamics::NotDeclaredByTheDescription;
using CircleCylinderIntersection = dynamics::NotDeclaredByTheDescription;
int detect_contacts = 0;
}  // namespace clearjoint::geometry

namespace clearjoint::dynamics {
namespace {

TEST(ModelDescription, CopiesWithEveryPartAndThePapersDefaults) {
  static_assert(std::is_copy_constructible_v<ModelDescription>);
  ModelDescription model;
  model.bodies.push_back({});
  model.forces.emplace_back(ClearanceRevoluteDescription{});
  ModelDescription copy = model;
  EXPECT_EQ(copy.bodies.size(), 1u);
  ASSERT_TRUE(std::holds_alternative<ClearanceRevoluteDescription>(copy.forces[0]));
  // The defaults of the plain parameter headers are the paper's (Table 2).
  const auto& joint = std::get<ClearanceRevoluteDescription>(copy.forces[0]);
  EXPECT_EQ(joint.parameters.dimensions.bearing_radius, 0.010);
  EXPECT_EQ(copy.solver.relative_tolerance, 1e-7);
  EXPECT_EQ(copy.baumgarte.alpha, 5.0);
}

}  // namespace
}  // namespace clearjoint::dynamics
