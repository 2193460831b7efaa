// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// What a clearance revolute joint is made of (clearance_revolute_joint.hpp), plain data: its
/// dimensions, force laws, detection options and oil film, without the joint or the detection.

#include <optional>

#include "clearjoint/dynamics/joint_lubrication.hpp"
#include "clearjoint/dynamics/normal_contact_force.hpp"
#include "clearjoint/dynamics/regularised_friction.hpp"
#include "clearjoint/geometry/model/detection_options.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/geometry/model/pin_in_hole_dimensions.hpp"

namespace clearjoint::dynamics {

struct ClearanceJointParameters {
  /// Ri, Li (bearing), Rj, Lj (journal); paper Table 2: 10, 20, 9.9, 19.8 mm.
  geometry::JointDimensions dimensions{0.010, 0.020, 0.0099, 0.0198};
  NormalForceParameters normal;
  FrictionParameters friction;
  geometry::DetectionOptions detection;
  /// The oil film; absent: a dry joint (the paper's). Not with pin_in_hole.
  std::optional<JointLubrication> lubrication;
  /// The pin-in-hole joint (docs/contact-detection.md, "The pin-in-hole joint") instead of the
  /// paper's journal-bearing: the bearing part is the hole, the journal part the pin, and
  /// `dimensions` is not used. Same force laws, friction and detection options.
  std::optional<geometry::PinInHoleDimensions> pin_in_hole;
};

}  // namespace clearjoint::dynamics
