// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/euler_parameters.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

namespace clearjoint::dynamics {
namespace {

// Rotation matrices from unit Euler parameters are exact up to a few ulps of 1.
constexpr double kRoundingTolerance = 1e-14;
// Central differences with h = 1e-6 on O(1) functions: truncation ~h^2, rounding ~1e-16/h.
constexpr double kFiniteDifferenceTolerance = 1e-9;

Vector4 random_unit_parameters(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Vector4 p(normal(rng), normal(rng), normal(rng), normal(rng));
  return p.normalized();
}

TEST(EulerParameters, GiveAProperRotationMatrix) {
  std::mt19937 rng(7);
  for (int k = 0; k < 100; ++k) {
    const Matrix3 A = rotation_from_euler_parameters(random_unit_parameters(rng));
    EXPECT_LT((A.transpose() * A - Matrix3::Identity()).norm(), kRoundingTolerance);
    EXPECT_NEAR(A.determinant(), 1.0, kRoundingTolerance);
  }
}

TEST(EulerParameters, AgreeWithEigenQuaternions) {
  std::mt19937 rng(8);
  for (int k = 0; k < 100; ++k) {
    const Vector4 p = random_unit_parameters(rng);
    const Eigen::Quaterniond q(p[0], p[1], p[2], p[3]);
    EXPECT_LT((rotation_from_euler_parameters(p) - q.toRotationMatrix()).norm(), kRoundingTolerance);
    const Vector4 back = euler_parameters_from_rotation(q.toRotationMatrix());
    EXPECT_LT(std::min((back - p).norm(), (back + p).norm()), kRoundingTolerance);
  }
}

TEST(EulerParameterRate, IsTheDerivativeOfABodyFrameRotation) {
  // p(t) = p0 * exp(omega' t / 2) rotates with constant body-frame angular velocity omega'.
  std::mt19937 rng(9);
  const double h = 1e-6;
  for (int k = 0; k < 20; ++k) {
    const Vector4 p = random_unit_parameters(rng);
    const Vector3 omega(0.3, -1.2, 2.0);
    auto at = [&](double t) {
      const Eigen::Quaterniond q =
          Eigen::Quaterniond(p[0], p[1], p[2], p[3]) *
          Eigen::Quaterniond(Eigen::AngleAxisd(omega.norm() * t, omega.normalized()));
      return Vector4(q.w(), q.x(), q.y(), q.z());
    };
    const Vector4 numeric = (at(h) - at(-h)) / (2 * h);
    EXPECT_LT((euler_parameter_rate(p, omega) - numeric).norm(), kFiniteDifferenceTolerance);
    EXPECT_NEAR(p.dot(euler_parameter_rate(p, omega)), 0.0, kRoundingTolerance);
  }
}

TEST(RotateInWorld, PremultipliesByTheWorldRotation) {
  const Vector4 p = euler_parameters_from_axis_angle(Vector3(1, 2, 3), 0.7);
  const Vector3 theta(0.1, -0.2, 0.3);
  const Matrix3 expected =
      Eigen::AngleAxisd(theta.norm(), theta.normalized()).toRotationMatrix() *
      rotation_from_euler_parameters(p);
  EXPECT_LT((rotation_from_euler_parameters(rotate_in_world(p, theta)) - expected).norm(),
            kRoundingTolerance);
}

}  // namespace
}  // namespace clearjoint::dynamics
