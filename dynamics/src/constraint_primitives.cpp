// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/constraint_primitives.hpp"

#include <cmath>

namespace clearjoint::dynamics {

namespace {

/// Value, world-frame angular Jacobians, first derivative and gamma of a_i . a_j.
struct DotProduct {
  double value;
  Vector3 jacobian_omega_i;
  Vector3 jacobian_omega_j;
  double rate;
  double gamma;
};

DotProduct dot_product(const BodyKinematics& i, const BodyKinematics& j, const Vector3& a_i,
                       const Vector3& a_j) {
  const Vector3& w_i = i.angular_velocity_W;
  const Vector3& w_j = j.angular_velocity_W;
  const Vector3 a_i_rate = w_i.cross(a_i);
  const Vector3 a_j_rate = w_j.cross(a_j);
  const Vector3 n = a_i.cross(a_j);
  DotProduct d;
  d.value = a_i.dot(a_j);
  // d/dt (a_i . a_j) = omega_i . (a_i x a_j) + omega_j . (a_j x a_i)
  d.jacobian_omega_i = n;
  d.jacobian_omega_j = -n;
  d.rate = a_i_rate.dot(a_j) + a_i.dot(a_j_rate);
  // Quadratic velocity terms of the second derivative, moved to the right-hand side.
  d.gamma = -(a_j.dot(w_i.cross(a_i_rate)) + 2.0 * a_i_rate.dot(a_j_rate) +
              a_i.dot(w_j.cross(a_j_rate)));
  return d;
}

}  // namespace

void ConstraintRows::to_body_frame(const Matrix3& rotation_i, const Matrix3& rotation_j) {
  jacobian_i.rightCols<3>() = jacobian_i.rightCols<3>() * rotation_i;
  jacobian_j.rightCols<3>() = jacobian_j.rightCols<3>() * rotation_j;
}

void add_coincident_points(ConstraintRows& rows, const BodyKinematics& i, const BodyKinematics& j,
                           const Vector3& s_i_W, const Vector3& s_j_W) {
  const int k = rows.count;
  rows.value.segment<3>(k) = j.position_W + s_j_W - i.position_W - s_i_W;
  rows.time_derivative.segment<3>(k).setZero();
  // d/dt (r + s) = rdot + omega x s = rdot - skew(s) omega
  rows.jacobian_i.block<3, 3>(k, 0) = -Matrix3::Identity();
  rows.jacobian_i.block<3, 3>(k, 3) = skew(s_i_W);
  rows.jacobian_j.block<3, 3>(k, 0) = Matrix3::Identity();
  rows.jacobian_j.block<3, 3>(k, 3) = -skew(s_j_W);
  const Vector3& w_i = i.angular_velocity_W;
  const Vector3& w_j = j.angular_velocity_W;
  rows.gamma.segment<3>(k) = w_i.cross(w_i.cross(s_i_W)) - w_j.cross(w_j.cross(s_j_W));
  rows.count += 3;
}

void add_perpendicular_vectors(ConstraintRows& rows, const BodyKinematics& i,
                               const BodyKinematics& j, const Vector3& a_i_W,
                               const Vector3& a_j_W) {
  const int k = rows.count;
  const DotProduct d = dot_product(i, j, a_i_W, a_j_W);
  rows.value[k] = d.value;
  rows.time_derivative[k] = 0.0;
  rows.jacobian_i.row(k).head<3>().setZero();
  rows.jacobian_i.row(k).tail<3>() = d.jacobian_omega_i.transpose();
  rows.jacobian_j.row(k).head<3>().setZero();
  rows.jacobian_j.row(k).tail<3>() = d.jacobian_omega_j.transpose();
  rows.gamma[k] = d.gamma;
  rows.count += 1;
}

void add_offset_perpendicular_to_vector(ConstraintRows& rows, const BodyKinematics& i,
                                        const BodyKinematics& j, const Vector3& a_i_W,
                                        const Vector3& s_i_W, const Vector3& s_j_W) {
  const int k = rows.count;
  const Vector3& w_i = i.angular_velocity_W;
  const Vector3& w_j = j.angular_velocity_W;
  const Vector3 d = j.position_W + s_j_W - i.position_W - s_i_W;
  const Vector3 d_rate = j.velocity_W + w_j.cross(s_j_W) - i.velocity_W - w_i.cross(s_i_W);
  const Vector3 a_i_rate = w_i.cross(a_i_W);
  rows.value[k] = a_i_W.dot(d);
  rows.time_derivative[k] = 0.0;
  // d/dt (a_i . d) = omega_i . (a_i x d) + a_i . (rdot_j + omega_j x s_j - rdot_i - omega_i x s_i)
  rows.jacobian_i.row(k).head<3>() = -a_i_W.transpose();
  rows.jacobian_i.row(k).tail<3>() = a_i_W.cross(d + s_i_W).transpose();
  rows.jacobian_j.row(k).head<3>() = a_i_W.transpose();
  rows.jacobian_j.row(k).tail<3>() = s_j_W.cross(a_i_W).transpose();
  const Vector3 d_centripetal = w_j.cross(w_j.cross(s_j_W)) - w_i.cross(w_i.cross(s_i_W));
  rows.gamma[k] =
      -(w_i.cross(a_i_rate).dot(d) + 2.0 * a_i_rate.dot(d_rate) + a_i_W.dot(d_centripetal));
  rows.count += 1;
}

void add_relative_angle(ConstraintRows& rows, const BodyKinematics& i, const BodyKinematics& j,
                        const Vector3& u_i_W, const Vector3& u_j_W, const Vector3& v_j_W,
                        const AngleValue& prescribed) {
  const int k = rows.count;
  const DotProduct x = dot_product(i, j, u_i_W, u_j_W);
  const DotProduct y = dot_product(i, j, u_i_W, v_j_W);
  const double s = std::sin(prescribed.angle);
  const double c = std::cos(prescribed.angle);
  const double w = prescribed.rate;
  const double a = prescribed.acceleration;
  const double s_rate = c * w;
  const double c_rate = -s * w;
  const double s_acceleration = -s * w * w + c * a;
  const double c_acceleration = -c * w * w - s * a;
  rows.value[k] = s * x.value + c * y.value;
  rows.time_derivative[k] = s_rate * x.value + c_rate * y.value;
  rows.jacobian_i.row(k).head<3>().setZero();
  rows.jacobian_i.row(k).tail<3>() = (s * x.jacobian_omega_i + c * y.jacobian_omega_i).transpose();
  rows.jacobian_j.row(k).head<3>().setZero();
  rows.jacobian_j.row(k).tail<3>() = (s * x.jacobian_omega_j + c * y.jacobian_omega_j).transpose();
  // Phi'' = s'' X + 2 s' X' + s X'' + (same with c, Y); X'' = (Jacobian part) - gamma_X.
  rows.gamma[k] = s * x.gamma + c * y.gamma -
                  (s_acceleration * x.value + c_acceleration * y.value + 2.0 * s_rate * x.rate +
                   2.0 * c_rate * y.rate);
  rows.count += 1;
}

}  // namespace clearjoint::dynamics
