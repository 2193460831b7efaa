// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/gravity.hpp"

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

Gravity::Gravity(std::vector<double> masses, const Vector3& acceleration_W)
    : masses_(std::move(masses)), acceleration_W_(acceleration_W) {
  require_finite("gravity", acceleration_W_);
}

void Gravity::add_forces(const ForceContext& /*context*/, GeneralisedForces& forces) const {
  for (BodyIndex b = 0; b < static_cast<BodyIndex>(masses_.size()); ++b) {
    forces.add_force(b, masses_[b] * acceleration_W_);
  }
}

double Gravity::potential_energy(const SystemKinematics& kinematics) const {
  double energy = 0.0;
  for (BodyIndex b = 0; b < static_cast<BodyIndex>(masses_.size()); ++b) {
    energy -= masses_[b] * acceleration_W_.dot(kinematics.body(b).position_W);
  }
  return energy;
}

}  // namespace clearjoint::dynamics
