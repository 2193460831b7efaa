#pragma once
/// \file
/// Everything a model file says: bodies with their initial states, joints, forces, how to make
/// the initial conditions consistent, solver settings and what to write. Plain data; see
/// model_file.hpp for the JSON form and model_builder.hpp for turning it into a system.

#include <string>
#include <variant>
#include <vector>

#include "clearjoint/dynamics/initial_conditions.hpp"
#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/joint_description.hpp"
#include "clearjoint/dynamics/spring_damper.hpp"

namespace clearjoint::dynamics {

struct BodyDescription {
  BodyProperties properties;
  BodyState initial;  ///< a guess: initial conditions correct it (see held_* below)
};

struct PointLoadDescription {
  std::string name;
  std::string body;
  Vector3 point_B = Vector3::Zero();
  Vector3 force_W = Vector3::Zero();
  Vector3 moment_W = Vector3::Zero();
};

struct SpringDamperDescription {
  std::string name;
  std::string body_i;
  std::string body_j;
  Vector3 point_i_B = Vector3::Zero();
  Vector3 point_j_B = Vector3::Zero();
  SpringDamperParameters parameters;
};

using ForceDescription = std::variant<PointLoadDescription, SpringDamperDescription>;

/// Component names: positions "x", "y", "z", "rx", "ry", "rz" (small rotations about the world
/// axes); velocities "vx", "vy", "vz", "wx", "wy", "wz" (world frame).
struct HeldPositionDescription {
  std::string body;
  std::string component;
};
struct HeldVelocityDescription {
  std::string body;
  std::string component;
  double value = 0.0;
};

struct ModelDescription {
  std::string name;
  std::string notes;
  Vector3 gravity_W = Vector3::Zero();
  std::vector<BodyDescription> bodies;
  std::vector<JointDescription> joints;
  std::vector<ForceDescription> forces;
  std::vector<HeldPositionDescription> held_positions;
  std::vector<HeldVelocityDescription> held_velocities;
  BaumgarteParameters baumgarte;
  IntegratorSettings solver;
  std::vector<std::string> output_bodies;  ///< bodies whose time series are written
};

}  // namespace clearjoint::dynamics
