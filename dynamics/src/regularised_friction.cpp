// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/regularised_friction.hpp"

#include <cmath>
#include <string>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

void validate(const FrictionParameters& p, std::string_view field) {
  const std::string f(field);
  require_finite(f + ".coefficient", p.coefficient);
  if (p.coefficient < 0.0) {
    throw ModelError(f + ".coefficient = " + format_number(p.coefficient) + ": must be >= 0");
  }
  require_positive(f + ".velocity_coefficient", p.velocity_coefficient);
}

Vector3 regularised_friction_force(const FrictionParameters& p, double normal_force,
                                   const Vector3& tangential_velocity_W) noexcept {
  const double speed = tangential_velocity_W.norm();
  if (!(normal_force > 0.0) || speed == 0.0 || p.coefficient == 0.0) return Vector3::Zero();
  // eq. (32) with sgn(v_T) = v_T / |v_T|. tanh(x) / x stays accurate as x -> 0 (libm's tanh is
  // accurate to an ulp for tiny x), so no series is needed near v_T = 0.
  const double magnitude = p.coefficient * normal_force *
                           std::tanh(p.velocity_coefficient * speed);  // eqs. (31)-(32)
  return (magnitude / speed) * tangential_velocity_W;
}

}  // namespace clearjoint::dynamics
