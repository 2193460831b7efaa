// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The tables clearjoint-mujoco writes, with the names, columns and units of `clearjoint
/// simulate`'s (dynamics/src/simulation.cpp), so that `clearjoint plot`, `view` and `read_run`
/// read its folder as any run folder (docs/engines.md, "The run folder"):
///   body_<name>  for every body but the world: time, x y z (the body frame's origin), e0..e3
///                (its orientation, MuJoCo's xquat), vx vy vz, wx wy wz (world frame), ax ay az,
///                alphax alphay alphaz (world frame, the body frame's origin) [m, m/s, m/s^2,
///                rad/s, rad/s^2]
///   energy       time, kinetic, potential, total [J]: MuJoCo's (mj_energyPos, mj_energyVel:
///                gravity and springs) plus the elastic energy in the clearance joints' contacts
///   force_<name> each clearance joint's columns (dynamics::ClearanceRevoluteJoint::output_columns)

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "clearjoint/dynamics/simulation.hpp"
#include "clearjoint/dynamics/simulation_output.hpp"
#include "clearjoint/mujoco/clearance_joints.hpp"

namespace clearjoint::mujoco_tool {

class RunTables {
 public:
  /// The plan for `model`'s bodies and `clearance`'s joints. Throws std::runtime_error when two
  /// tables' file names coincide (the names are compared as `clearjoint simulate` compares them).
  RunTables(mjModel* model, const mujoco::ClearanceJoints& clearance);

  const std::vector<dynamics::TablePlan>& tables() const { return tables_; }

  /// Declare the tables in `output` (once).
  void declare(dynamics::SimulationOutput& output);
  /// One row of every table at `data`'s state, after mj_forward at that state (so that its
  /// derived quantities are the state's, not those of mj_step's last stage).
  void write(mjData* data, dynamics::SimulationOutput& output);

  double initial_energy() const { return initial_energy_; }
  double max_energy_change() const { return max_energy_change_; }

 private:
  mjModel* model_;
  const mujoco::ClearanceJoints& clearance_;
  std::vector<int> bodies_;
  std::vector<dynamics::TablePlan> tables_;
  std::vector<std::size_t> index_;
  std::vector<double> row_;
  bool first_row_ = true;
  double initial_energy_ = 0.0;
  double max_energy_change_ = 0.0;
};

}  // namespace clearjoint::mujoco_tool
