// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The applied part of eq. (35)'s generalised force vector g, accumulated per body as a force at
/// the mass centre and a moment about it, both in the world frame. MultibodySystem turns them into
/// g = [f; A^T n - omega' x J' omega'] (the gyroscopic term is added there, not here).

#include <vector>

#include "clearjoint/dynamics/system_kinematics.hpp"

namespace clearjoint::dynamics {

class GeneralisedForces {
 public:
  explicit GeneralisedForces(const SystemKinematics& kinematics);

  /// Zero every body's force and moment (no allocation).
  void clear();

  /// A force through the mass centre. Forces on the ground are dropped (it does not move).
  void add_force(BodyIndex b, const Vector3& force_W);
  /// A force applied at a point given in the world frame: adds (p - r) x f to the moment.
  void add_force_at_point(BodyIndex b, const Vector3& force_W, const Vector3& point_W);
  /// A pure moment (couple).
  void add_moment(BodyIndex b, const Vector3& moment_W);

  const Vector3& force_W(BodyIndex b) const { return forces_W_[b]; }
  const Vector3& moment_W(BodyIndex b) const { return moments_W_[b]; }

 private:
  const SystemKinematics* kinematics_;
  std::vector<Vector3> forces_W_;
  std::vector<Vector3> moments_W_;
};

}  // namespace clearjoint::dynamics
