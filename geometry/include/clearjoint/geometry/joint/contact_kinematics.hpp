// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Velocities at a contact: paper eqs. (24)-(26).

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/arithmetic/vector3.hpp"

namespace clearjoint::geometry {

/// A rigid body's motion at one instant, all in the world frame W: mass-centre position r,
/// its velocity r_dot, angular velocity omega.
struct BodyMotion {
  Vector3 p_WM = Vector3::Zero();
  Vector3 v_WM = Vector3::Zero();
  Vector3 w_W = Vector3::Zero();
};

/// Convention: `approach_speed` > 0 while the journal point moves further into the bearing
/// surface along Contact::normal_W (penetration growing), < 0 while separating.
struct ContactKinematics {
  Vector3 v_WCi = Vector3::Zero();  ///< velocity of the bearing's material point at C_i, eq. (25)
  Vector3 v_WCj = Vector3::Zero();  ///< velocity of the journal's material point at C_j, eq. (25)
  double approach_speed = 0.0;      ///< delta_dot = (v_Cj - v_Ci) . n, eq. (24)
  /// v_T = (v_Cj - v_Ci) - delta_dot n, eq. (26); orthogonal to n up to rounding.
  Vector3 tangential_velocity_W = Vector3::Zero();
};

/// Evaluate eqs. (24)-(26) for one contact; `bearing` is body i, `journal` body j.
ContactKinematics contact_kinematics(const Contact& contact, const BodyMotion& bearing,
                                     const BodyMotion& journal) noexcept;

}  // namespace clearjoint::geometry
