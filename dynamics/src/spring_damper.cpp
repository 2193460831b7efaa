// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/spring_damper.hpp"

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

namespace {

void require_non_negative(const std::string& field, double value) {
  require_finite(field, value);
  if (value < 0.0) throw ModelError(field + " = " + format_number(value) + ": must be >= 0");
}

}  // namespace

void validate_spring_damper(std::string_view name, const Vector3& point_i_B, const Vector3& point_j_B,
                            const SpringDamperParameters& parameters) {
  const std::string prefix(name);
  require_finite(prefix + ".point_i", point_i_B);
  require_finite(prefix + ".point_j", point_j_B);
  require_non_negative(prefix + ".stiffness", parameters.stiffness);
  require_non_negative(prefix + ".damping", parameters.damping);
  require_non_negative(prefix + ".free_length", parameters.free_length);
}

SpringDamper::SpringDamper(std::string name, BodyIndex body_i, const Vector3& point_i_B,
                           BodyIndex body_j, const Vector3& point_j_B,
                           const SpringDamperParameters& parameters)
    : name_(std::move(name)), body_i_(body_i), point_i_B_(point_i_B), body_j_(body_j),
      point_j_B_(point_j_B), parameters_(parameters) {
  validate_spring_damper(name_, point_i_B_, point_j_B_, parameters_);
}

void SpringDamper::add_forces(const ForceContext& context, GeneralisedForces& forces) const {
  const BodyKinematics& i = context.kinematics.body(body_i_);
  const BodyKinematics& j = context.kinematics.body(body_j_);
  const Vector3 p_i = i.point_W(point_i_B_);
  const Vector3 p_j = j.point_W(point_j_B_);
  const Vector3 d = p_j - p_i;
  const double length = d.norm();
  if (!(length >= kSpringMinimumLength)) {
    throw SolverError("spring-damper '" + name_ + "' at t = " + format_number(context.time) +
                      ": length " + format_number(length) +
                      " m, its line of action is undefined");
  }
  const Vector3 direction = d / length;
  const double length_rate = direction.dot(j.point_velocity_W(point_j_B_) - i.point_velocity_W(point_i_B_));
  const double tension = parameters_.stiffness * (length - parameters_.free_length) +
                         parameters_.damping * length_rate;
  forces.add_force_at_point(body_i_, tension * direction, p_i);
  forces.add_force_at_point(body_j_, -tension * direction, p_j);
}

double SpringDamper::potential_energy(const SystemKinematics& kinematics) const {
  const double length = (kinematics.body(body_j_).point_W(point_j_B_) -
                         kinematics.body(body_i_).point_W(point_i_B_)).norm();
  const double stretch = length - parameters_.free_length;
  return 0.5 * parameters_.stiffness * stretch * stretch;
}

}  // namespace clearjoint::dynamics
