// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/kernel_pose.hpp"

#include <cmath>

namespace clearjoint::dynamics {

Vector3 flush_negligible_coordinates(const Vector3& p_W) {
  Vector3 flushed = p_W;
  for (int k = 0; k < 3; ++k) {
    // NaN compares false and stays: the kernel names it.
    if (std::abs(flushed[k]) < kNegligibleCoordinate) flushed[k] = 0.0;
  }
  return flushed;
}

geometry::PartPose kernel_pose(const BodyKinematics& body, const Vector3& point_B, const Vector3& axis_B) {
  return {flush_negligible_coordinates(body.point_W(point_B)), body.rotation * axis_B};
}

}  // namespace clearjoint::dynamics
