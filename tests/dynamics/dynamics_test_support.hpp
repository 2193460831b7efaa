// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Small models shared by the dynamics tests.

#include <cmath>
#include <string>

#include "clearjoint/dynamics/model_description.hpp"
#include "clearjoint/dynamics/model_file.hpp"

namespace clearjoint::dynamics::test {

inline constexpr double kStandardGravity = 9.81;

/// A compound pendulum: body "bob" (mass m, equal principal moments I_c) whose mass centre hangs a
/// distance `length` below a revolute joint at the origin (axis z), released from rest at angle
/// theta0 from the downward vertical; gravity -y.
struct PendulumParameters {
  double mass = 1.0;
  double central_inertia = 0.01;
  double length = 0.5;
  double initial_angle = 0.01;
};

inline ModelDescription pendulum_model(const PendulumParameters& p) {
  ModelDescription model;
  model.name = "pendulum";
  model.gravity_W = Vector3(0.0, -kStandardGravity, 0.0);
  BodyDescription bob;
  bob.properties = {"bob", p.mass, Vector3::Constant(p.central_inertia)};
  bob.initial.position_W =
      Vector3(p.length * std::sin(p.initial_angle), -p.length * std::cos(p.initial_angle), 0.0);
  bob.initial.euler_parameters = euler_parameters_from_axis_angle(Vector3::UnitZ(), p.initial_angle);
  model.bodies.push_back(bob);
  JointDescription pivot;
  pivot.name = "pivot";
  pivot.type = JointType::revolute;
  pivot.body_i = "ground";
  pivot.body_j = "bob";
  pivot.point_j_B = Vector3(0.0, p.length, 0.0);
  model.joints.push_back(pivot);
  model.output_bodies = {"bob"};
  return model;
}

inline ModelDescription shipped_model(const std::string& file) {
  return read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/" + file);
}

}  // namespace clearjoint::dynamics::test
