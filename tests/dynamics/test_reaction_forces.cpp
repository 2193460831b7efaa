// SPDX-License-Identifier: BSD-3-Clause
// Reaction forces from the multipliers (eq. 37) against hand computations.

#include "clearjoint/dynamics/reaction_forces.hpp"

#include <gtest/gtest.h>

#include "clearjoint/dynamics/model_builder.hpp"

namespace clearjoint::dynamics {
namespace {

// Hand results are exact; the solve loses a few ulps of the O(10 N) forces.
constexpr double kForceTolerance = 1e-12;

constexpr double kGravity = 9.81;
constexpr double kMass = 2.0;
constexpr double kLength = 0.6;

ModelDescription horizontal_beam(JointType joint_type) {
  // A uniform beam of length L along +x, its left end at the origin, gravity -z.
  ModelDescription model;
  model.gravity_W = Vector3(0, 0, -kGravity);
  BodyDescription beam;
  const double central = kMass * kLength * kLength / 12.0;
  beam.properties = {"beam", kMass, Vector3(central / 100.0, central, central)};
  beam.initial.position_W = Vector3(kLength / 2, 0, 0);
  model.bodies.push_back(beam);
  JointDescription support;
  support.name = "support";
  support.type = joint_type;
  support.body_i = "ground";
  support.body_j = "beam";
  support.point_j_B = Vector3(-kLength / 2, 0, 0);
  support.axis_i_B = support.axis_j_B = Vector3::UnitY();
  model.joints.push_back(support);
  model.output_bodies = {"beam"};
  return model;
}

TEST(JointReaction, HoldsAClampedBeamAgainstGravity) {
  // Static: the clamp carries the weight m g and the moment m g L/2 about the clamp point.
  BuiltModel built = build_model(horizontal_beam(JointType::fixed));
  std::vector<double> rate(built.initial_state.size());
  built.system->derivative(0.0, built.initial_state, rate);
  EXPECT_LT(built.system->accelerations().cwiseAbs().maxCoeff(), kForceTolerance);
  const JointReaction r = joint_reaction(*built.system, 0);
  EXPECT_EQ(r.body, 0);
  EXPECT_LT((r.force_W - Vector3(0, 0, kMass * kGravity)).norm(), kForceTolerance);
  // Gravity's moment about the clamp: (L/2, 0, 0) x (0, 0, -m g) = (0, m g L/2, 0); the clamp
  // balances it.
  EXPECT_LT((r.moment_W - Vector3(0, -kMass * kGravity * kLength / 2, 0)).norm(), kForceTolerance);
}

TEST(JointReaction, CarriesAQuarterOfTheWeightOfABeamReleasedFromAHinge) {
  // Released from rest, horizontal, hinged at one end about y: I_O alpha = m g L/2 with
  // I_O = m L^2/3 gives alpha = 3 g/(2 L); the mass centre falls at a = alpha L/2 = 3 g/4, so the
  // hinge pushes up with m (g - a) = m g/4, and no moment about the hinge axis.
  BuiltModel built = build_model(horizontal_beam(JointType::revolute));
  std::vector<double> rate(built.initial_state.size());
  built.system->derivative(0.0, built.initial_state, rate);
  const Eigen::VectorXd& a = built.system->accelerations();
  EXPECT_NEAR(a[2], -0.75 * kGravity, kForceTolerance);
  const JointReaction r = joint_reaction(*built.system, 0);
  EXPECT_LT((r.force_W - Vector3(0, 0, kMass * kGravity / 4)).norm(), kForceTolerance);
  EXPECT_NEAR(r.moment_W.y(), 0.0, kForceTolerance);
}

}  // namespace
}  // namespace clearjoint::dynamics
