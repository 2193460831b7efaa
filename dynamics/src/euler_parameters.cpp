// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/euler_parameters.hpp"

#include <Eigen/Geometry>

namespace clearjoint::dynamics {

namespace {

Eigen::Quaterniond to_quaternion(const Vector4& p) { return {p[0], p[1], p[2], p[3]}; }

Vector4 from_quaternion(Eigen::Quaterniond q) {
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // p and -p are the same rotation; keep e0 >= 0
  return {q.w(), q.x(), q.y(), q.z()};
}

}  // namespace

Matrix3 rotation_from_euler_parameters(const Vector4& p) {
  const double e0 = p[0];
  const Vector3 e = p.tail<3>();
  return (2.0 * e0 * e0 - 1.0) * Matrix3::Identity() + 2.0 * (e * e.transpose() + e0 * skew(e));
}

Vector4 euler_parameter_rate(const Vector4& p, const Vector3& angular_velocity_B) {
  const double e0 = p[0];
  const Vector3 e = p.tail<3>();
  Vector4 rate;
  rate[0] = -0.5 * e.dot(angular_velocity_B);
  rate.tail<3>() = 0.5 * (e0 * angular_velocity_B + e.cross(angular_velocity_B));
  return rate;
}

Vector4 euler_parameters_from_rotation(const Matrix3& rotation) {
  return from_quaternion(Eigen::Quaterniond(rotation).normalized());
}

Vector4 euler_parameters_from_axis_angle(const Vector3& axis, double angle) {
  return from_quaternion(Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized())));
}

Vector4 rotate_in_world(const Vector4& p, const Vector3& theta_W) {
  const double angle = theta_W.norm();
  Eigen::Quaterniond increment = Eigen::Quaterniond::Identity();
  if (angle > 0.0) increment = Eigen::Quaterniond(Eigen::AngleAxisd(angle, theta_W / angle));
  return from_quaternion((increment * to_quaternion(p)).normalized());
}

}  // namespace clearjoint::dynamics
