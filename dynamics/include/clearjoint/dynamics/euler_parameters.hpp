// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Euler parameters p = (e0, e1, e2, e3) = (e0, e), the paper's rotational coordinates: the
/// rotation matrix they define, their time derivative from the body-frame angular velocity, and
/// conversions used to set up models.
///
/// Convention: A(p) maps body-frame components to world components, x_W = r + A(p) x_B.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace clearjoint::dynamics {

using Vector3 = Eigen::Vector3d;
using Vector4 = Eigen::Vector4d;
using Matrix3 = Eigen::Matrix3d;

/// 3x3 cross-product matrix: skew(a) * b = a x b.
inline Matrix3 skew(const Vector3& a) {
  Matrix3 s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

/// A = (2 e0^2 - 1) I + 2 (e e^T + e0 skew(e)). Precondition: |p| = 1 (callers normalise first;
/// the integrator lets |p| drift and the system reports that drift).
Matrix3 rotation_from_euler_parameters(const Vector4& p);

/// dp/dt = 1/2 L(p)^T omega_B with L(p) = [-e, -skew(e) + e0 I]: the kinematic relation between
/// the Euler-parameter rates and the body-frame angular velocity. It keeps |p| constant in exact
/// arithmetic because p^T L(p)^T = 0.
Vector4 euler_parameter_rate(const Vector4& p, const Vector3& angular_velocity_B);

/// Unit Euler parameters of a proper rotation matrix (e0 >= 0).
Vector4 euler_parameters_from_rotation(const Matrix3& rotation);

/// Euler parameters of the rotation by `angle` radians about the unit `axis`.
Vector4 euler_parameters_from_axis_angle(const Vector3& axis, double angle);

/// p of the rotation "first p, then rotate by the world-frame rotation vector theta_W":
/// A(result) = exp(skew(theta_W)) A(p). Used by the position corrector.
Vector4 rotate_in_world(const Vector4& p, const Vector3& theta_W);

}  // namespace clearjoint::dynamics
