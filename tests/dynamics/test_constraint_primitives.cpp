// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/constraint_primitives.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace clearjoint::dynamics {
namespace {

constexpr double kRoundingTolerance = 1e-15;

BodyKinematics at_rest(const Matrix3& rotation) {
  BodyKinematics k;
  k.rotation = rotation;
  return k;
}

TEST(RelativeAngle, IsTheSineOfTheAngleError) {
  // Body j turned by theta about z relative to body i: Phi = sin(theta(t) - theta).
  for (double theta : {-2.5, -0.3, 0.0, 0.9, 3.0}) {
    for (double prescribed : {-1.0, 0.0, 0.4, 2.0}) {
      const Matrix3 Rj = Eigen::AngleAxisd(theta, Vector3::UnitZ()).toRotationMatrix();
      const BodyKinematics i = at_rest(Matrix3::Identity());
      const BodyKinematics j = at_rest(Rj);
      ConstraintRows rows;
      add_relative_angle(rows, i, j, Vector3::UnitX(), Rj * Vector3::UnitX(), Rj * Vector3::UnitY(),
                         {prescribed, 0.0, 0.0});
      ASSERT_EQ(rows.count, 1);
      EXPECT_NEAR(rows.value[0], std::sin(prescribed - theta), kRoundingTolerance);
    }
  }
}

TEST(CoincidentPoints, MeasuresTheGapFromPointIToPointJ) {
  BodyKinematics i = at_rest(Matrix3::Identity());
  BodyKinematics j = at_rest(Matrix3::Identity());
  i.position_W = Vector3(1, 0, 0);
  j.position_W = Vector3(0, 2, 0);
  ConstraintRows rows;
  add_coincident_points(rows, i, j, Vector3(0, 0, 1), Vector3(0, 0, 3));
  ASSERT_EQ(rows.count, 3);
  EXPECT_EQ(Vector3(rows.value.head<3>()), Vector3(-1, 2, 2));
}

TEST(ConstraintRows, ConvertWorldAngularColumnsToBodyFrame) {
  ConstraintRows rows;
  rows.count = 1;
  rows.jacobian_i.row(0) << 0, 0, 0, 1, 2, 3;
  const Matrix3 A = Eigen::AngleAxisd(0.5, Vector3(1, 1, 0).normalized()).toRotationMatrix();
  rows.to_body_frame(A, Matrix3::Identity());
  // d(Phi)/d(omega') = d(Phi)/d(omega_W) A since omega_W = A omega'.
  EXPECT_LT((Vector3(rows.jacobian_i.row(0).tail<3>().transpose()) -
             A.transpose() * Vector3(1, 2, 3)).norm(), kRoundingTolerance * 10);
}

}  // namespace
}  // namespace clearjoint::dynamics
