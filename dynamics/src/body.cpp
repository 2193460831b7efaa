// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/body.hpp"

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

void validate(const BodyProperties& body, std::string_view field) {
  const std::string prefix(field);
  if (body.name.empty()) throw ModelError(prefix + ".name is empty: every body needs a name");
  if (body.name == kGroundName) {
    throw ModelError(prefix + ".name = \"ground\": the name is reserved for the world frame");
  }
  require_positive(prefix + ".mass", body.mass);
  for (int k = 0; k < 3; ++k) {
    require_positive(prefix + ".inertia[" + std::to_string(k) + "]", body.principal_inertia[k]);
  }
}

void validate(const BodyState& state, std::string_view field) {
  const std::string prefix(field);
  require_finite(prefix + ".position", state.position_W);
  require_nonzero(prefix + ".euler_parameters", state.euler_parameters);
  require_finite(prefix + ".velocity", state.velocity_W);
  require_finite(prefix + ".angular_velocity", state.angular_velocity_B);
}

}  // namespace clearjoint::dynamics
