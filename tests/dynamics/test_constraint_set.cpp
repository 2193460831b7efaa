// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/constraint_set.hpp"

#include <gtest/gtest.h>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {
namespace {

JointDescription revolute(const std::string& name, const Vector3& point_j) {
  JointDescription j;
  j.name = name;
  j.type = JointType::revolute;
  j.body_i = "ground";
  j.body_j = "door";
  j.point_j_B = point_j;
  return j;
}

TEST(ConstraintSet, StacksJointsRowByRow) {
  SystemKinematics k(1);
  k.set(0, BodyState{});
  std::vector<JointEquations> joints;
  joints.push_back(JointEquations::build(revolute("hinge", Vector3::Zero()), kGround, 0, k));
  JointDescription driver;
  driver.name = "motor";
  driver.type = JointType::angle_driver;
  driver.body_i = "ground";
  driver.body_j = "door";
  joints.push_back(JointEquations::build(driver, kGround, 0, k));
  ConstraintSet set(std::move(joints), 1);
  EXPECT_EQ(set.equation_count(), 6);
  EXPECT_EQ(set.first_row(1), 5);
  set.evaluate(0.0, k);
  EXPECT_EQ(set.jacobian().rows(), 6);
  EXPECT_EQ(set.jacobian().cols(), 6);
  EXPECT_NO_THROW(set.require_independent_rows());
  EXPECT_EQ(set.describe_row(5), "joint 'motor' (angle_driver), equation 0");
}

TEST(ConstraintSet, AssemblesTheStackedRowsOnlyWhenAskedFor) {
  SystemKinematics k(1);
  BodyState door;
  door.angular_velocity_B = Vector3(0.0, 0.0, 2.0);
  k.set(0, door);
  std::vector<JointEquations> joints;
  joints.push_back(JointEquations::build(revolute("hinge", Vector3(0.0, 0.3, 0.0)), kGround, 0, k));
  ConstraintSet set(std::move(joints), 1);
  set.evaluate(0.0, k);
  set.evaluate(0.0, k);
  EXPECT_EQ(set.dense_assemblies(), 0) << "evaluate() stacked rows nobody read";
  // Once per evaluation asked for, whichever array is asked first; the copy is the joint's rows.
  EXPECT_EQ(set.jacobian().block(0, 0, 5, 6), set.joint_rows(0).jacobian_j.topRows(5));
  EXPECT_EQ(set.gamma(), set.joint_rows(0).gamma.head(5));
  EXPECT_EQ(set.value(), set.joint_rows(0).value.head(5));
  EXPECT_EQ(set.time_derivative(), set.joint_rows(0).time_derivative.head(5));
  EXPECT_EQ(set.dense_assemblies(), 1);
  door.angular_velocity_B = Vector3(0.0, 0.0, -1.0);
  k.set(0, door);
  set.evaluate(0.0, k);
  EXPECT_EQ(set.gamma(), set.joint_rows(0).gamma.head(5)) << "the stacked rows kept an old evaluation";
  EXPECT_EQ(set.dense_assemblies(), 2);
}

TEST(ConstraintSet, NamesTheJointThatMakesTheConstraintsRedundant) {
  // Two hinges on the same axis: the second adds no independent equation (all five redundant).
  SystemKinematics k(1);
  k.set(0, BodyState{});
  std::vector<JointEquations> joints;
  joints.push_back(JointEquations::build(revolute("upper hinge", Vector3(0, 0, 0.5)), kGround, 0, k));
  JointDescription lower = revolute("lower hinge", Vector3(0, 0, -0.5));
  lower.point_i_B = Vector3(0, 0, -0.5);
  lower.point_j_B = Vector3(0, 0, -0.5);
  joints.push_back(JointEquations::build(lower, kGround, 0, k));
  ConstraintSet set(std::move(joints), 1);
  set.evaluate(0.0, k);
  try {
    set.require_independent_rows();
    FAIL() << "redundant hinges were accepted";
  } catch (const SolverError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'lower hinge'"), std::string::npos) << message;
    EXPECT_NE(message.find("adds only 0 independent equation(s) of 5"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace clearjoint::dynamics
