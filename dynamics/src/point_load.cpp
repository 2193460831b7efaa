// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/point_load.hpp"

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

PointLoad::PointLoad(std::string name, BodyIndex body, const Vector3& point_B,
                     const Vector3& force_W, const Vector3& moment_W)
    : name_(std::move(name)), body_(body), point_B_(point_B), force_W_(force_W),
      moment_W_(moment_W) {
  require_finite(name_ + ".point", point_B_);
  require_finite(name_ + ".force", force_W_);
  require_finite(name_ + ".moment", moment_W_);
}

void PointLoad::add_forces(const ForceContext& context, GeneralisedForces& forces) const {
  forces.add_force_at_point(body_, force_W_, context.kinematics.body(body_).point_W(point_B_));
  forces.add_moment(body_, moment_W_);
}

double PointLoad::potential_energy(const SystemKinematics& kinematics) const {
  return -force_W_.dot(kinematics.body(body_).point_W(point_B_));
}

}  // namespace clearjoint::dynamics
