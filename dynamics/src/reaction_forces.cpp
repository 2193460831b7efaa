// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/reaction_forces.hpp"

namespace clearjoint::dynamics {

JointReaction joint_reaction(const MultibodySystem& system, int joint) {
  return joint_reaction(system, joint, system.multipliers());
}

JointReaction joint_reaction(const MultibodySystem& system, int joint, const Eigen::VectorXd& multipliers) {
  const ConstraintSet& constraints = system.constraints();
  const JointEquations& equations = constraints.joints()[joint];
  const bool on_j = equations.body_j() != kGround;
  JointReaction reaction;
  reaction.body = on_j ? equations.body_j() : equations.body_i();
  if (reaction.body == kGround) return reaction;

  const int row = constraints.first_row(joint);
  const int count = equations.equation_count();
  // eq. (37), restricted to this joint's rows and this body's six columns.
  const Eigen::Matrix<double, 6, 1> generalised =
      -constraints.jacobian().block(row, 6 * reaction.body, count, 6).transpose() *
      multipliers.segment(row, count);
  const BodyKinematics& k = system.kinematics().body(reaction.body);
  reaction.force_W = generalised.head<3>();
  const Vector3 moment_about_centre_W = k.rotation * generalised.tail<3>();
  const Vector3& point_B = on_j ? equations.point_j_B() : equations.point_i_B();
  reaction.moment_W = moment_about_centre_W - (k.rotation * point_B).cross(reaction.force_W);
  return reaction;
}

}  // namespace clearjoint::dynamics
