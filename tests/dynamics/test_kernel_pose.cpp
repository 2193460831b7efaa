// SPDX-License-Identifier: BSD-3-Clause
// The conversion of a part's pose from a body's state to the geometry kernel's input
// (kernel_pose.hpp): negligible centre coordinates become 0, everything else passes as it is.
#include "clearjoint/dynamics/kernel_pose.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace clearjoint::dynamics {
namespace {

TEST(KernelPose, FlushesACoordinateBelowTheKernelsSmallestLengthToZero) {
  const Vector3 flushed = flush_negligible_coordinates(Vector3(0.456, -2.3e-41, -8.7e-165));
  EXPECT_EQ(flushed, Vector3(0.456, -2.3e-41, 0.0));
  // Subnormals and the largest double below the threshold alike.
  const double just_below = std::nextafter(geometry::kSmallestAcceptedLength, 0.0);
  EXPECT_EQ(flush_negligible_coordinates(Vector3(just_below, -4.9e-324, -just_below)), Vector3::Zero());
}

TEST(KernelPose, PassesACoordinateAtOrAboveTheThresholdAndANonFiniteOneAsItIs) {
  const double smallest = geometry::kSmallestAcceptedLength;
  const Vector3 kept(smallest, -smallest, 1e300);
  EXPECT_EQ(flush_negligible_coordinates(kept), kept);
  // The kernel names a non-finite coordinate: it must reach it.
  const Vector3 not_finite = flush_negligible_coordinates(
      Vector3(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), 0.0));
  EXPECT_TRUE(std::isnan(not_finite.x()));
  EXPECT_EQ(not_finite.y(), std::numeric_limits<double>::infinity());
}

TEST(KernelPose, IsTheBodysPointAndAxisInTheWorldWithTheCentreFlushedAndTheAxisAsItIs) {
  BodyKinematics body;
  body.position_W = Vector3(0.25, 1e-170, 0.0);
  // A quarter turn about x, then a tilt of 1e-160 rad: out-of-plane entries far below 1e-150.
  body.rotation << 1.0, 0.0, 0.0,  //
      0.0, 0.0, -1.0,              //
      1e-160, 1.0, 0.0;
  const Vector3 point_B(0.5, 0.0, 0.0), axis_B(1.0, 0.0, 1.0);
  const geometry::PartPose pose = kernel_pose(body, point_B, axis_B);
  EXPECT_EQ(body.point_W(point_B), Vector3(0.75, 1e-170, 5e-161));
  EXPECT_EQ(pose.p_WP, Vector3(0.75, 0.0, 0.0));
  EXPECT_EQ(pose.axis_W, body.rotation * axis_B);
  EXPECT_EQ(pose.axis_W.z(), 1e-160);  // a direction: the kernel takes it (joint_geometry.hpp)
}

}  // namespace
}  // namespace clearjoint::dynamics
