// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/joint_description.hpp"

#include <string>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

namespace {

bool uses_axes(JointType type) {
  return type != JointType::spherical && type != JointType::fixed;
}

}  // namespace

std::string_view to_string(JointType type) { return geometry::key_of(type); }

JointType joint_type_from_string(std::string_view name, std::string_view field) {
  if (const auto type = geometry::from_string<JointType>(name)) return *type;
  throw ModelError(std::string(field) + " = \"" + std::string(name) + "\": unknown joint type (known: " +
                   geometry::known_keys<JointType>() + ")");
}

int equation_count(JointType type) {
  switch (type) {
    case JointType::spherical: return 3;
    case JointType::revolute: return 5;
    case JointType::universal: return 4;
    case JointType::cylindrical: return 4;
    case JointType::translational: return 5;
    case JointType::fixed: return 6;
    case JointType::angle_driver: return 1;
  }
  return 0;
}

void validate(const JointDescription& joint, std::string_view field) {
  const std::string prefix(field);
  if (joint.name.empty()) throw ModelError(prefix + ".name is empty: every joint needs a name");
  if (joint.body_i.empty()) throw ModelError(prefix + ".body_i is empty");
  if (joint.body_j.empty()) throw ModelError(prefix + ".body_j is empty");
  if (joint.body_i == joint.body_j) {
    throw ModelError(prefix + ": body_i and body_j are both \"" + joint.body_i +
                     "\": a joint connects two different bodies");
  }
  require_finite(prefix + ".point_i", joint.point_i_B);
  require_finite(prefix + ".point_j", joint.point_j_B);
  if (uses_axes(joint.type)) {
    require_nonzero(prefix + ".axis_i", joint.axis_i_B);
    if (joint.type != JointType::angle_driver) require_nonzero(prefix + ".axis_j", joint.axis_j_B);
  }
  require_finite(prefix + ".angle.rate", joint.angle.rate);
  require_finite(prefix + ".angle.acceleration", joint.angle.acceleration);
}

}  // namespace clearjoint::dynamics
