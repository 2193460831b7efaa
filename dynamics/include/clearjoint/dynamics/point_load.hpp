// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A constant world-frame force at a body-fixed point and a constant world-frame moment.

#include <string>

#include "clearjoint/dynamics/force_element.hpp"

namespace clearjoint::dynamics {

class PointLoad final : public ForceElement {
 public:
  PointLoad(std::string name, BodyIndex body, const Vector3& point_B, const Vector3& force_W,
            const Vector3& moment_W);

  std::string_view name() const override { return name_; }
  void add_forces(const ForceContext& context, GeneralisedForces& forces) const override;
  /// -f . x_P: a constant force is conservative. A constant world moment is not (its work depends
  /// on the path of the rotation), so it contributes nothing here.
  double potential_energy(const SystemKinematics& kinematics) const override;

 private:
  std::string name_;
  BodyIndex body_;
  Vector3 point_B_;
  Vector3 force_W_;
  Vector3 moment_W_;
};

}  // namespace clearjoint::dynamics
