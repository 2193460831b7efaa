// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The journal's motion relative to its bearing: all a film needs to know about velocities.

#include "clearjoint/geometry/arithmetic/vector3.hpp"

namespace clearjoint::lubrication {

using geometry::Vector3;

/// The journal's velocity as seen from the bearing body (a frame that moves and turns with the
/// bearing), expressed in the world frame W. From the two bodies' world velocities:
///   v_BJ_W = v_WJ - v_WB - omega_WB x (p_WJ - p_WB),   omega_BJ_W = omega_WJ - omega_WB,
/// with p_WJ, p_WB the parts' centres. In this frame the bearing wall is still, the journal's
/// surface moves at omega_BJ . a_B times its radius around the bearing's axis a_B (the wedge
/// term), and the journal's axis moves across the film (the squeeze term).
struct RelativeMotion {
  Vector3 v_BJ_W = Vector3::Zero();      ///< velocity of the journal's centre P_j, m/s
  Vector3 omega_BJ_W = Vector3::Zero();  ///< angular velocity of the journal, rad/s
};

}  // namespace clearjoint::lubrication
