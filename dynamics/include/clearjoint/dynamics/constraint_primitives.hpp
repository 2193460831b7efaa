// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The building blocks every ideal joint is assembled from (Nikravesh's spherical, dot-1 and dot-2
/// constraints, plus a relative-angle driver). Each adds rows of eq. (33) Phi, their explicit time
/// derivative, their Jacobian (eq. 34's Phi_q) and the right-hand side gamma of eq. (34).
///
/// Derivation (docs/dynamics.md): a vector fixed in body k has a_W = A_k a', so
/// da_W/dt = omega_k x a_W and d2a_W/dt2 = alpha_k x a_W + omega_k x (omega_k x a_W), with
/// alpha_k = A_k domega'_k/dt exactly. The primitives therefore work in the world frame with
/// columns for [rdot_k; omega_k(world)]; ConstraintRows::to_body_frame() then multiplies the
/// angular columns by A_k to get columns for [rdot_k; omega'_k], the velocity coordinates.

#include <Eigen/Core>

#include "clearjoint/dynamics/angle_law.hpp"
#include "clearjoint/dynamics/system_kinematics.hpp"

namespace clearjoint::dynamics {

/// The fixed joint, with 6 equations, is the largest.
inline constexpr int kMaxJointEquations = 6;

/// Rows of one joint: Phi, dPhi/dt (explicit), Phi_q split into the 6 columns of body i and of
/// body j, and gamma = -(dPhi_q/dt) v - d2Phi/dt2 (explicit), so that Phi_q dv/dt = gamma.
struct ConstraintRows {
  using Column = Eigen::Matrix<double, kMaxJointEquations, 1>;
  using Block = Eigen::Matrix<double, kMaxJointEquations, 6>;

  int count = 0;
  Column value = Column::Zero();
  Column time_derivative = Column::Zero();
  Block jacobian_i = Block::Zero();
  Block jacobian_j = Block::Zero();
  Column gamma = Column::Zero();

  /// Turn the angular columns from world-frame omega to body-frame omega' (multiply by A).
  void to_body_frame(const Matrix3& rotation_i, const Matrix3& rotation_j);
};

/// Three rows: r_j + s_j - r_i - s_i = 0 (points coincide). s_* are the points' offsets from
/// their mass centres, in the world frame.
void add_coincident_points(ConstraintRows& rows, const BodyKinematics& i, const BodyKinematics& j,
                           const Vector3& s_i_W, const Vector3& s_j_W);

/// One row (dot-1): a_i . a_j = 0, two body-fixed vectors stay perpendicular.
void add_perpendicular_vectors(ConstraintRows& rows, const BodyKinematics& i,
                               const BodyKinematics& j, const Vector3& a_i_W, const Vector3& a_j_W);

/// One row (dot-2): a_i . d = 0 with d = (r_j + s_j) - (r_i + s_i): the segment between two points
/// stays perpendicular to a vector fixed in body i.
void add_offset_perpendicular_to_vector(ConstraintRows& rows, const BodyKinematics& i,
                                        const BodyKinematics& j, const Vector3& a_i_W,
                                        const Vector3& s_i_W, const Vector3& s_j_W);

/// One row: the rotation of body j relative to body i about the common axis equals theta(t).
/// u_i is fixed in i; u_j and v_j are fixed in j, all perpendicular to the axis, with u_j = u_i
/// and v_j = axis x u_i when the relative angle is zero. With X = u_i.u_j = cos(theta) and
/// Y = u_i.v_j = -sin(theta), the row is Phi = sin(theta(t)) X + cos(theta(t)) Y
/// = sin(theta(t) - theta): smooth, and its gradient has unit size at the solution.
void add_relative_angle(ConstraintRows& rows, const BodyKinematics& i, const BodyKinematics& j,
                        const Vector3& u_i_W, const Vector3& u_j_W, const Vector3& v_j_W,
                        const AngleValue& prescribed);

}  // namespace clearjoint::dynamics
