// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/generalised_forces.hpp"

namespace clearjoint::dynamics {

GeneralisedForces::GeneralisedForces(const SystemKinematics& kinematics)
    : kinematics_(&kinematics),
      forces_W_(static_cast<size_t>(kinematics.body_count()), Vector3::Zero()),
      moments_W_(static_cast<size_t>(kinematics.body_count()), Vector3::Zero()) {}

void GeneralisedForces::clear() {
  for (Vector3& f : forces_W_) f.setZero();
  for (Vector3& n : moments_W_) n.setZero();
}

void GeneralisedForces::add_force(BodyIndex b, const Vector3& force_W) {
  if (b == kGround) return;
  forces_W_[b] += force_W;
}

void GeneralisedForces::add_force_at_point(BodyIndex b, const Vector3& force_W,
                                           const Vector3& point_W) {
  if (b == kGround) return;
  forces_W_[b] += force_W;
  moments_W_[b] += (point_W - kinematics_->body(b).position_W).cross(force_W);
}

void GeneralisedForces::add_moment(BodyIndex b, const Vector3& moment_W) {
  if (b == kGround) return;
  moments_W_[b] += moment_W;
}

}  // namespace clearjoint::dynamics
