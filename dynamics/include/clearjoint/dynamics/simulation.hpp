// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A whole run: build the model, integrate it, and write the CSV time series (or hand the same
/// tables to a SimulationOutput).
///
/// Files in the output directory (one row per report time):
///   body_<name>.csv  time, x, y, z, e0..e3, vx, vy, vz, wx, wy, wz (world), ax, ay, az,
///                    alphax, alphay, alphaz (world) for every output body
///   energy.csv       time, kinetic, potential, total, position_violation (max |Phi|),
///                    velocity_violation (max |Phi_q v + Phi_t|), euler_norm_drift (max ||p|-1|)
///   reactions.csv    time, then per joint `<joint>.fx` .. `<joint>.mz`: the reaction (eq. 37) on
///                    body j (body i for joints to ground), moment about the joint point, world frame
///   force_<name>.csv time, then the columns a force element records (ForceElement::output_columns;
///                    e.g. a clearance joint's contact depths, forces, scenario), for every element
///                    that records any
/// In body_<name> and force_<name>, characters other than letters, digits, - and _ of the name
/// become _ (also in the table names of TablesInMemory); two files whose names then match, also
/// without case, are refused before the run starts.

#include <filesystem>
#include <functional>

#include "clearjoint/dynamics/model_builder.hpp"
#include "clearjoint/dynamics/simulation_output.hpp"

namespace clearjoint::dynamics {

struct SimulationSummary {
  IntegrationStatistics integration;
  InitialConditionReport initial_conditions;
  double initial_energy = 0.0;
  double max_energy_change = 0.0;  ///< max |E(t) - E(0)| over report times [J]
  double max_position_violation = 0.0;
  double max_velocity_violation = 0.0;
  double max_euler_norm_drift = 0.0;
  std::vector<std::string> element_statistics;  ///< ForceElement::statistics_text(), non-empty ones
};

/// progress(fraction in [0, 1]) is called at report times and, between them, after an accepted
/// step when 0.1 s of wall time has passed since the last such call (may be empty). It may throw to stop the run (a user's interrupt): the exception
/// leaves simulate() and no output is committed.
using ProgressCallback = std::function<void(double fraction)>;

/// Run `model` and write the files above into `output_directory` (created if missing). Each file
/// appears only when complete (CsvWriter); OutputFolder (output_folder.hpp) publishes the whole
/// folder as one unit. Throws ModelError, SolverError or std::runtime_error.
SimulationSummary simulate(const ModelDescription& model,
                           const std::filesystem::path& output_directory,
                           const ProgressCallback& progress = {});

/// Run `model` and send the same tables to `output` (simulation_output.hpp): named like the files
/// above without ".csv" ("energy", "body_crank", ...), with the same columns and values.
/// TablesInMemory keeps them in memory. Throws as above.
SimulationSummary simulate(const ModelDescription& model, SimulationOutput& output,
                           const ProgressCallback& progress = {});

}  // namespace clearjoint::dynamics
