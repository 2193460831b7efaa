// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Uniform gravity: m g at every mass centre; potential energy -sum m g . r.

#include <vector>

#include "clearjoint/dynamics/body.hpp"
#include "clearjoint/dynamics/force_element.hpp"

namespace clearjoint::dynamics {

/// The name of the gravity element build_model adds (model_builder.hpp).
inline constexpr std::string_view kGravityName = "gravity";

class Gravity final : public ForceElement {
 public:
  /// `masses[b]` of every body; `acceleration_W` e.g. (0, 0, -9.81) m/s^2.
  Gravity(std::vector<double> masses, const Vector3& acceleration_W);

  std::string_view name() const override { return kGravityName; }
  void add_forces(const ForceContext& context, GeneralisedForces& forces) const override;
  double potential_energy(const SystemKinematics& kinematics) const override;

 private:
  std::vector<double> masses_;
  Vector3 acceleration_W_;
};

}  // namespace clearjoint::dynamics
