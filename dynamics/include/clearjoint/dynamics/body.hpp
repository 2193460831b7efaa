// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A rigid body as a model describes it: inertial properties, and a state in the paper's
/// coordinates (mass-centre position r and Euler parameters p) with its velocities.

#include <string>
#include <string_view>

#include "clearjoint/dynamics/euler_parameters.hpp"

namespace clearjoint::dynamics {

/// Index of a body in a system; the ground (world frame, at rest) has the index kGround.
using BodyIndex = int;
inline constexpr BodyIndex kGround = -1;
inline constexpr std::string_view kGroundName = "ground";

/// Mass and principal moments of inertia about the mass centre, in the body frame (whose axes are
/// the principal axes). Preconditions (checked by validate()): finite, mass > 0, each moment > 0.
/// Triangle inequalities on the moments are not required here (tests use point-like bodies);
/// model files must obey them (model_file.cpp).
struct BodyProperties {
  std::string name;
  double mass = 0.0;
  Vector3 principal_inertia = Vector3::Zero();
};

/// Position and velocity of one body: r and p (eq. 33's coordinates q for this body), the
/// mass-centre velocity in the world frame and the angular velocity in the body frame.
struct BodyState {
  Vector3 position_W = Vector3::Zero();
  Vector4 euler_parameters{1.0, 0.0, 0.0, 0.0};
  Vector3 velocity_W = Vector3::Zero();
  Vector3 angular_velocity_B = Vector3::Zero();
};

/// Throw ModelError naming `field` (e.g. "bodies[2]") unless the properties are usable.
void validate(const BodyProperties& body, std::string_view field);
/// Throw ModelError unless the state is finite and |p| is not zero.
void validate(const BodyState& state, std::string_view field);

}  // namespace clearjoint::dynamics
