// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Joint reaction forces from the Lagrange multipliers, eq. (37): g(c) = -Phi_q^T lambda.

#include "clearjoint/dynamics/multibody_system.hpp"

namespace clearjoint::dynamics {

/// The force a joint applies to one of its bodies, and its moment about the joint point on that
/// body, both in the world frame.
struct JointReaction {
  BodyIndex body = kGround;
  Vector3 force_W = Vector3::Zero();
  Vector3 moment_W = Vector3::Zero();
};

/// Reaction of joint `joint` on body j (on body i when body j is the ground), from the multipliers
/// of the last system.derivative() call: the joint's rows of -Phi_q^T lambda give the force and
/// the body-frame moment about the mass centre; the moment is then rotated to the world frame and
/// carried to the joint point P: n_P = n_c - (P - r) x f.
JointReaction joint_reaction(const MultibodySystem& system, int joint);

/// The same from given multipliers (one per constraint row of system.constraints(), whose
/// Jacobian is the last evaluated): a scheme that computes its own, such as Moreau-Jean's mean
/// -impulse / h over a step (clearjoint::nonsmooth).
JointReaction joint_reaction(const MultibodySystem& system, int joint, const Eigen::VectorXd& multipliers);

}  // namespace clearjoint::dynamics
