// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A linear translational spring-damper between two body-fixed points:
/// f = (k (l - l0) + c dl/dt) along the line, pulling the points together when positive.

#include <string>

#include "clearjoint/dynamics/force_element.hpp"
#include "clearjoint/dynamics/spring_damper_parameters.hpp"

namespace clearjoint::dynamics {

/// Below this length (metres) the line of action is undefined; evaluation throws SolverError.
/// 1e-12 m is far below any part of a mechanism and far above rounding of metre-scale positions.
inline constexpr double kSpringMinimumLength = 1e-12;

/// The checks SpringDamper's constructor makes: finite points, constants >= 0, each named
/// "<name>.<field>"; also for an engine that builds its own spring from the model's description.
void validate_spring_damper(std::string_view name, const Vector3& point_i_B, const Vector3& point_j_B,
                            const SpringDamperParameters& parameters);

class SpringDamper final : public ForceElement {
 public:
  SpringDamper(std::string name, BodyIndex body_i, const Vector3& point_i_B, BodyIndex body_j,
               const Vector3& point_j_B, const SpringDamperParameters& parameters);

  std::string_view name() const override { return name_; }
  void add_forces(const ForceContext& context, GeneralisedForces& forces) const override;
  /// k (l - l0)^2 / 2.
  double potential_energy(const SystemKinematics& kinematics) const override;

 private:
  std::string name_;
  BodyIndex body_i_;
  Vector3 point_i_B_;
  BodyIndex body_j_;
  Vector3 point_j_B_;
  SpringDamperParameters parameters_;
};

}  // namespace clearjoint::dynamics
