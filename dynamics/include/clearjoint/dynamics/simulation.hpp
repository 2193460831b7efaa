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
///   force_<name>.csv time, then the columns a force element records (ForceRecorder::output_columns;
///                    e.g. a clearance joint's contact depths, forces, scenario), for every element
///                    that records any (recorded_by_run)
/// In body_<name> and force_<name>, characters other than letters, digits, - and _ of the name
/// become _ (also in the table names of TablesInMemory); two files whose names then match, also
/// without case, are refused before the run starts.

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "clearjoint/dynamics/force_recorder.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "clearjoint/dynamics/model_overrides.hpp"
#include "clearjoint/dynamics/run_size.hpp"
#include "clearjoint/dynamics/simulation_output.hpp"
#include "clearjoint/dynamics/simulator.hpp"

namespace clearjoint::dynamics {

struct SimulationSummary {
  IntegrationStatistics integration;
  InitialConditionReport initial_conditions;
  double initial_energy = 0.0;
  double max_energy_change = 0.0;  ///< max |E(t) - E(0)| over report times [J]
  double max_position_violation = 0.0;
  double max_velocity_violation = 0.0;
  double max_euler_norm_drift = 0.0;
  std::vector<std::string> element_statistics;  ///< ForceRecorder::statistics_text(), non-empty ones
  /// The values set in place of the model file's (model_overrides.hpp), set by the caller that
  /// applied them; the run does not see them (its model has them written in).
  ModelOverrides overrides;
};

/// The summary as strict JSON text, one key per field (steps, derivative_calls, smallest_step,
/// largest_step, restarts, failed_attempts, located_onsets, onset_probes,
/// initial_condition_iterations, initial_position_residual, initial_velocity_residual,
/// initial_energy, max_energy_change, max_position_violation, max_velocity_violation,
/// max_euler_norm_drift, element_statistics, overrides: {path: value} in the order given, {} for
/// none): summary.json of a run folder, the Python dict.
std::string summary_json(const SimulationSummary& summary);

/// progress(fraction in [0, 1]) is called at report times and, between them, after an accepted
/// step when 0.1 s of wall time has passed since the last such call (may be empty). It may throw to stop the run (a user's interrupt): the exception
/// leaves simulate() and no output is committed.
using ProgressCallback = std::function<void(double fraction)>;

/// The one way a name from the model becomes a table name, and so a file name (<table>.csv):
/// `prefix` + the name with letters, digits, '-' and '_' kept and every other byte '_' (no '/',
/// no "..", no control characters). Model files keep names to kMaxNameBytes (model_file.hpp), so
/// the file name fits any file system. Engine adapters name their tables with it too.
std::string table_name(std::string_view prefix, std::string_view name);

/// The recorder of `element` when a run writes its table force_<name>: the element records
/// columns (ForceRecorder) and the model's output.force_elements lists it (or is absent, which
/// lists every element). Null otherwise. The compliant and the non-smooth runs pick their tables
/// with it.
const ForceRecorder* recorded_by_run(const ForceElement& element, const ModelDescription& model);

struct RunOptions {
  /// Run beyond the size guard (run_size.hpp); the command line's --allow-large.
  bool allow_large = false;
};

/// One run, planned before it starts: the model is built once (Simulator), the tables it will
/// write (names, columns) are decided and checked (names that collide), and the size guard
/// looks at that plan, all before any output exists. run() then integrates and writes the
/// tables to any SimulationOutput (CsvDirectory, TablesInMemory, an HDF5 file), writing the rows
/// of every output.decimation-th report time and of the last (the summary sees every report).
class SimulationRun {
 public:
  /// Throws ModelError (a bad model, colliding table names, a run beyond the size guard) or
  /// SolverError (inconsistent initial conditions).
  explicit SimulationRun(const ModelDescription& model, const RunOptions& options = {});
  SimulationRun(const SimulationRun&) = delete;
  SimulationRun& operator=(const SimulationRun&) = delete;
  ~SimulationRun();

  /// The tables, in the order they are declared to the output.
  const std::vector<TablePlan>& tables() const { return tables_; }
  const RunSize& size() const { return size_; }
  const ModelDescription& model() const { return simulator_->model(); }

  /// Integrate and write; once per SimulationRun. Throws SolverError or what `output` throws;
  /// `output` is committed only after the last row.
  SimulationSummary run(SimulationOutput& output, const ProgressCallback& progress = {});

 private:
  struct Sources;
  std::unique_ptr<Simulator> simulator_;
  std::unique_ptr<Sources> sources_;
  std::vector<TablePlan> tables_;
  RunSize size_;
  bool ran_ = false;
};

/// Run `model` and write the files above into `output_directory` (created if missing). Each file
/// appears only when complete (CsvWriter); OutputFolder (output_folder.hpp) publishes the whole
/// folder as one unit. No size guard (SimulationRun has it). Throws ModelError, SolverError or
/// std::runtime_error.
SimulationSummary simulate(const ModelDescription& model,
                           const std::filesystem::path& output_directory,
                           const ProgressCallback& progress = {});

/// Run `model` and send the same tables to `output` (simulation_output.hpp): named like the files
/// above without ".csv" ("energy", "body_crank", ...), with the same columns and values.
/// TablesInMemory keeps them in memory. Throws as above.
SimulationSummary simulate(const ModelDescription& model, SimulationOutput& output,
                           const ProgressCallback& progress = {});

}  // namespace clearjoint::dynamics
