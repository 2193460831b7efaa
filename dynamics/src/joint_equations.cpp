// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/joint_equations.hpp"

namespace clearjoint::dynamics {

Vector3 unit_perpendicular(const Vector3& axis) {
  Eigen::Index smallest = 0;
  axis.cwiseAbs().minCoeff(&smallest);
  return axis.cross(Vector3::Unit(smallest)).normalized();
}

JointEquations JointEquations::build(const JointDescription& joint, BodyIndex i, BodyIndex j,
                                     const SystemKinematics& initial) {
  JointEquations eq;
  eq.name_ = joint.name;
  eq.type_ = joint.type;
  eq.body_i_ = i;
  eq.body_j_ = j;
  eq.point_i_B_ = joint.point_i_B;
  eq.point_j_B_ = joint.point_j_B;

  const Vector3 h_i = joint.axis_i_B.normalized();
  const Vector3 h_j = joint.axis_j_B.normalized();
  const Vector3 u_i = unit_perpendicular(h_i);
  const Vector3 v_i = h_i.cross(u_i);
  // Body-i vectors expressed in body j's frame at t = 0: A_j^T A_i a'.
  const Matrix3 i_to_j = initial.body(j).rotation.transpose() * initial.body(i).rotation;
  auto add_pair = [&eq](const Vector3& a_i, const Vector3& a_j) {
    eq.perpendicular_pairs_[eq.perpendicular_pair_count_++] = {a_i, a_j};
  };
  auto add_offset = [&eq](const Vector3& a_i) {
    eq.offset_normals_i_B_[eq.offset_normal_count_++] = a_i;
  };

  switch (joint.type) {
    case JointType::spherical:
      eq.points_coincide_ = true;
      break;
    case JointType::revolute:
      eq.points_coincide_ = true;
      add_pair(u_i, h_j);
      add_pair(v_i, h_j);
      break;
    case JointType::universal:
      eq.points_coincide_ = true;
      add_pair(h_i, h_j);
      break;
    case JointType::cylindrical:
    case JointType::translational:
      add_pair(u_i, h_j);
      add_pair(v_i, h_j);
      add_offset(u_i);
      add_offset(v_i);
      if (joint.type == JointType::translational) add_pair(u_i, i_to_j * v_i);
      break;
    case JointType::fixed: {
      eq.points_coincide_ = true;
      // Body i's frame axes x, y, z against their images in body j at t = 0.
      const Vector3 x = Vector3::UnitX(), y = Vector3::UnitY(), z = Vector3::UnitZ();
      add_pair(x, i_to_j * y);
      add_pair(x, i_to_j * z);
      add_pair(y, i_to_j * z);
      break;
    }
    case JointType::angle_driver:
      eq.has_driver_ = true;
      eq.driver_ = {u_i, i_to_j * u_i, i_to_j * v_i, joint.angle};
      break;
  }
  return eq;
}

void JointEquations::evaluate(double time, const SystemKinematics& kinematics,
                              ConstraintRows& rows) const {
  const BodyKinematics& i = kinematics.body(body_i_);
  const BodyKinematics& j = kinematics.body(body_j_);
  rows.count = 0;
  const Vector3 s_i = i.rotation * point_i_B_;
  const Vector3 s_j = j.rotation * point_j_B_;
  if (points_coincide_) add_coincident_points(rows, i, j, s_i, s_j);
  for (int k = 0; k < perpendicular_pair_count_; ++k) {
    const VectorPair& pair = perpendicular_pairs_[k];
    add_perpendicular_vectors(rows, i, j, i.rotation * pair.a_i_B, j.rotation * pair.a_j_B);
  }
  for (int k = 0; k < offset_normal_count_; ++k) {
    add_offset_perpendicular_to_vector(rows, i, j, i.rotation * offset_normals_i_B_[k], s_i, s_j);
  }
  if (has_driver_) {
    add_relative_angle(rows, i, j, i.rotation * driver_.u_i_B, j.rotation * driver_.u_j_B,
                       j.rotation * driver_.v_j_B, driver_.law.at(time));
  }
  rows.to_body_frame(i.rotation, j.rotation);
}

}  // namespace clearjoint::dynamics
