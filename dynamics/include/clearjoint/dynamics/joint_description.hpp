// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// An ideal joint as a user or a model file describes it: which bodies, which points and axes in
/// each body frame. joint_equations.hpp turns it into constraint equations.

#include <array>
#include <string>
#include <string_view>

#include "clearjoint/dynamics/angle_law.hpp"
#include "clearjoint/dynamics/euler_parameters.hpp"  // Vector3
#include "clearjoint/geometry/model/enum_table.hpp"

namespace clearjoint::dynamics {

enum class JointType {
  spherical,      ///< 3 equations: the two points coincide
  revolute,       ///< 5: points coincide, axes stay parallel (paper: "five equations", Sec. 5)
  universal,      ///< 4: points coincide, the two cross axes stay perpendicular
  cylindrical,    ///< 4: axes stay parallel and on one line
  translational,  ///< 5: cylindrical, and the relative rotation about the axis is locked
  fixed,          ///< 6: points coincide, relative orientation locked
  angle_driver,   ///< 1: relative rotation about an axis prescribed in time (drives a crank)
};

}  // namespace clearjoint::dynamics

/// The model-file spellings of the joint types.
template <>
struct clearjoint::geometry::EnumTable<clearjoint::dynamics::JointType> {
  using J = clearjoint::dynamics::JointType;
  static constexpr std::string_view type_name = "JointType";
  static constexpr auto entries = std::to_array({
      named_entry(J::spherical, "spherical", "3 equations: the two points coincide"),
      named_entry(J::revolute, "revolute", "5 equations: points coincide, axes stay parallel"),
      named_entry(J::universal, "universal", "4 equations: points coincide, the cross axes stay perpendicular"),
      named_entry(J::cylindrical, "cylindrical", "4 equations: axes stay parallel and on one line"),
      named_entry(J::translational, "translational", "5 equations: cylindrical, rotation about the axis locked"),
      named_entry(J::fixed, "fixed", "6 equations: points coincide, relative orientation locked"),
      named_entry(J::angle_driver, "angle_driver", "1 equation: rotation about an axis prescribed in time"),
  });
};
static_assert(clearjoint::geometry::entries_in_code_order<clearjoint::dynamics::JointType>());

namespace clearjoint::dynamics {

/// The key of the type's entry in its table (the model-file spelling).
std::string_view to_string(JointType type);
/// Throws ModelError naming `field` for an unknown name.
JointType joint_type_from_string(std::string_view name, std::string_view field);
/// Number of constraint equations of a joint of this type.
int equation_count(JointType type);

/// The user-facing joint. Points and axes are in the frames of body_i and body_j; axes need not
/// be unit. What each type reads:
///   spherical      point_i, point_j
///   revolute       point_i, point_j, axis_i, axis_j (the same line in the world)
///   universal      point_i, point_j, axis_i, axis_j (the cross axes, perpendicular)
///   cylindrical    point_i, point_j (on the axis), axis_i, axis_j
///   translational  as cylindrical; the relative rotation about the axis is the one at t = 0
///   fixed          point_i, point_j; the relative orientation is the one at t = 0
///   angle_driver   axis_i, angle (body j turns about axis_i by angle(t) from its t = 0 pose)
/// "At t = 0" means the poses the model gives before the initial conditions are made consistent.
struct JointDescription {
  std::string name;
  JointType type = JointType::spherical;
  std::string body_i;
  std::string body_j;
  Vector3 point_i_B = Vector3::Zero();
  Vector3 point_j_B = Vector3::Zero();
  Vector3 axis_i_B = Vector3::UnitZ();
  Vector3 axis_j_B = Vector3::UnitZ();
  AngleLaw angle;
};

/// Throw ModelError naming `field` (e.g. "joints[2]") for unusable values: empty names, the same
/// body twice, non-finite numbers, zero axes.
void validate(const JointDescription& joint, std::string_view field);

}  // namespace clearjoint::dynamics
