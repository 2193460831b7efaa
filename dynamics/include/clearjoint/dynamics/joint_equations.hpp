// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A joint's constraint equations (eqs. 33-34) as the solver needs them: body indices and
/// body-frame vectors, assembled from the primitives of constraint_primitives.hpp. Built once from
/// a JointDescription; evaluate() does no allocation.

#include <array>
#include <string>

#include "clearjoint/dynamics/constraint_primitives.hpp"
#include "clearjoint/dynamics/joint_description.hpp"

namespace clearjoint::dynamics {

class JointEquations {
 public:
  /// Resolve `joint` between bodies i and j (either may be kGround). `initial` gives the poses at
  /// t = 0, used by the joints that lock a relative orientation (translational, fixed,
  /// angle_driver). Axes are normalised here.
  static JointEquations build(const JointDescription& joint, BodyIndex i, BodyIndex j,
                              const SystemKinematics& initial);

  /// Rows of Phi, dPhi/dt, Phi_q (columns for [rdot; omega'] of i and j) and gamma at `time`.
  void evaluate(double time, const SystemKinematics& kinematics, ConstraintRows& rows) const;

  const std::string& name() const { return name_; }
  JointType type() const { return type_; }
  BodyIndex body_i() const { return body_i_; }
  BodyIndex body_j() const { return body_j_; }
  int equation_count() const { return dynamics::equation_count(type_); }
  /// The joint point on each body, in its frame: where reaction forces are reported.
  const Vector3& point_i_B() const { return point_i_B_; }
  const Vector3& point_j_B() const { return point_j_B_; }

 private:
  struct VectorPair {
    Vector3 a_i_B;
    Vector3 a_j_B;
  };
  struct Driver {
    Vector3 u_i_B;
    Vector3 u_j_B;
    Vector3 v_j_B;
    AngleLaw law;
  };

  std::string name_;
  JointType type_ = JointType::spherical;
  BodyIndex body_i_ = kGround;
  BodyIndex body_j_ = kGround;
  bool points_coincide_ = false;
  Vector3 point_i_B_ = Vector3::Zero();
  Vector3 point_j_B_ = Vector3::Zero();
  std::array<VectorPair, 3> perpendicular_pairs_{};
  int perpendicular_pair_count_ = 0;
  std::array<Vector3, 2> offset_normals_i_B_{};  ///< dot-2 rows: a_i . (P_j - P_i) = 0
  int offset_normal_count_ = 0;
  bool has_driver_ = false;
  Driver driver_{};
};

/// A unit vector perpendicular to `axis` (deterministic: crosses with the coordinate axis of the
/// smallest |component|).
Vector3 unit_perpendicular(const Vector3& axis);

}  // namespace clearjoint::dynamics
