// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A part's pose as the dynamics hands it to the geometry kernel (contact detection, the film's
/// geometry): the one conversion from a body's state, for every caller that detects from a state
/// (the clearance joint, and through it the Simbody and MuJoCo engines; the non-smooth
/// integrator's contacts).

#include "clearjoint/dynamics/system_kinematics.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"

namespace clearjoint::dynamics {

/// A world coordinate of a part's centre smaller in magnitude than this is handed to the kernel
/// as exactly 0: the kernel accepts a coordinate that is 0 or of magnitude in
/// [kSmallestAcceptedLength, kLargestAcceptedLength] (its a-priori error bounds would underflow
/// below; joint_geometry.hpp), and the dynamics' rounding produces such coordinates where a
/// planar motion's out-of-plane coordinate should be 0 (9.6e-181 m at the misaligned planar
/// slider-crank's bearing after 0.25 ms of Moreau-Jean steps). Why it is harmless: 1e-150 m is physically zero, some 130 orders of magnitude
/// below the kernel's own error bounds on a joint of millimetres to metres, so the flushed pose
/// is the same joint to every digit the detection can resolve. What it changes: only such
/// coordinates; one at or above the threshold, and a non-finite one (which the kernel then
/// refuses by name), is passed as it is.
inline constexpr double kNegligibleCoordinate = geometry::kSmallestAcceptedLength;

/// `p_W` with every component of magnitude below kNegligibleCoordinate set to exactly 0.
Vector3 flush_negligible_coordinates(const Vector3& p_W);

/// The pose of a part fixed in `body` at `point_B` with axis `axis_B` (body frame): its centre
/// r + A s' through flush_negligible_coordinates, its axis A a' as it is. An axis needs no flush:
/// the kernel takes any finite, non-zero direction (it normalises it with an exact power-of-two
/// rescaling, joint_geometry.cpp's unit_axis), and A a' of an axis the model accepted is neither
/// zero nor out of range (|A a'| = |a'| to rounding; the model refuses an axis whose length
/// cannot be normalised).
geometry::PartPose kernel_pose(const BodyKinematics& body, const Vector3& point_B, const Vector3& axis_B);

}  // namespace clearjoint::dynamics
