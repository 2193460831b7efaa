// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// One run written into its output folder, the way `clearjoint simulate --out DIR` and Python's
/// simulate(out=DIR) both do it (docs/command-line.md, "Output folder"): the tables as CSV files
/// (<table>.csv) or one HDF5 file (run.h5, hdf5_tables.hpp), model.json (the model run) and
/// summary.json (summary_json), written into a staging folder and published as one unit
/// (OutputFolder).

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "clearjoint/dynamics/simulation.hpp"

namespace clearjoint::dynamics {

enum class RunFormat { csv, hdf5 };

/// "csv" or "hdf5": the one check of a run's format for every front-end; otherwise, or for hdf5
/// when this build has no HDF5, a ValidationError whose path is the caller's `field`
/// ("--format", "format") and whose message names the value.
RunFormat run_format(const std::string& name, std::string_view field = "format");
/// Whether this build writes HDF5.
bool hdf5_available();

struct RunFolderOptions {
  RunFormat format = RunFormat::csv;
  bool replace_existing = false;  ///< --force: replace an earlier result (OutputFolder)
  /// The values set in place of the model file's (already written into model_json), recorded in
  /// summary.json.
  ModelOverrides overrides;
};

/// Runs `run` into `destination`. `model_json` is written as model.json (and into run.h5).
/// The folder is claimed (OutputFolder's checks) before the first step. Throws what the run,
/// the folder or the writers throw; a failed run leaves the destination as it was.
SimulationSummary write_run_folder(SimulationRun& run, const std::string& model_json,
                                   const std::filesystem::path& destination, const RunFolderOptions& options,
                                   const ProgressCallback& progress = {});

/// The same folder for a run made elsewhere (another engine): `run_into(output)` writes its tables
/// to the format's sink (CsvDirectory or Hdf5Tables in the staging folder), commits it and returns
/// the summary. The first overload is this one with SimulationRun::run.
SimulationSummary write_run_folder(const std::function<SimulationSummary(SimulationOutput&)>& run_into,
                                   const std::string& model_json, const std::filesystem::path& destination,
                                   const RunFolderOptions& options);

}  // namespace clearjoint::dynamics
