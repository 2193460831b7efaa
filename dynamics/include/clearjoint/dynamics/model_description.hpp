// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Everything a model file says: bodies with their initial states, joints, forces, how to make
/// the initial conditions consistent, solver settings and what to write. Plain data; see
/// model_file.hpp for the JSON form and model_builder.hpp for turning it into a system.

#include <string>
#include <variant>
#include <vector>

// Only plain parameter headers: a description depends on no equations, integrator or kernel
// query (tests/dynamics/test_model_description.cpp does not compile if one comes back).
#include "clearjoint/dynamics/baumgarte_parameters.hpp"
#include "clearjoint/dynamics/body.hpp"
#include "clearjoint/dynamics/clearance_joint_parameters.hpp"
#include "clearjoint/dynamics/integrator_settings.hpp"
#include "clearjoint/dynamics/joint_description.hpp"
#include "clearjoint/dynamics/solver_method.hpp"
#include "clearjoint/dynamics/spring_damper_parameters.hpp"

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

/// One cylinder of a clearance joint as a model names it.
struct ClearancePartDescription {
  std::string body;
  Vector3 point_B = Vector3::Zero();  ///< P, centre of the cylinder's axis segment, body frame
  Vector3 axis_B = Vector3::UnitZ();  ///< a, body frame
};

/// A revolute joint with clearance between a bearing and a journal (force element, not a
/// constraint); dimensions, force law, friction and detection options in `parameters`.
struct ClearanceRevoluteDescription {
  std::string name;
  ClearancePartDescription bearing;
  ClearancePartDescription journal;
  ClearanceJointParameters parameters;
};

using ForceDescription =
    std::variant<PointLoadDescription, SpringDamperDescription, ClearanceRevoluteDescription>;

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
  /// solver.method: the compliant integrator (solver above) or Moreau-Jean (moreau_jean below).
  SolverMethod solver_method = SolverMethod::dormand_prince;
  MoreauJeanSettings moreau_jean;  ///< solver.step, theta, contact_* (read for moreau_jean only)
  std::vector<std::string> output_bodies;  ///< bodies whose time series are written
  /// Force elements whose outputs (force_<name>.csv) are written; all of them by default.
  std::vector<std::string> output_force_elements;
  bool output_all_force_elements = true;
  /// Rows are written at every output_decimation-th report time and at end_time (the summary's
  /// extremes still see every report time); model files: output.decimation.
  long output_decimation = 1;
};

/// Largest output.decimation (a whole number; beyond it a long run would write only its ends).
inline constexpr double kMaxDecimation = 1e9;

}  // namespace clearjoint::dynamics
