// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/joint/contact_kinematics.hpp"

namespace clearjoint::geometry {
namespace {

/// eq. (25): r_dot_C = r_dot + omega x s_C, with s_C = r_C - r the point measured from the
/// mass centre.
Vector3 material_point_velocity(const BodyMotion& body, const Vector3& p_WC) {
  return body.v_WM + body.w_W.cross(p_WC - body.p_WM);
}

}  // namespace

ContactKinematics contact_kinematics(const Contact& contact, const BodyMotion& bearing,
                                     const BodyMotion& journal) noexcept {
  ContactKinematics out;
  out.v_WCi = material_point_velocity(bearing, contact.p_WCi);
  out.v_WCj = material_point_velocity(journal, contact.p_WCj);
  const Vector3 relative = out.v_WCj - out.v_WCi;
  out.approach_speed = relative.dot(contact.normal_W);                           // eq. (24)
  out.tangential_velocity_W = relative - out.approach_speed * contact.normal_W;  // eq. (26)
  return out;
}

}  // namespace clearjoint::geometry
