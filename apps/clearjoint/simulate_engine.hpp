// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The engine that integrates `clearjoint simulate --engine NAME`: clearjoint's own (the default)
// or Simbody (engines/simbody, docs/engines.md), both writing the tables of one plan
// (dynamics::SimulationRun) to one sink (dynamics::SimulationOutput), so that the format, the
// decimation and the columns are the same whichever engine runs.

#include <functional>
#include <string>
#include <string_view>

#include "clearjoint/dynamics/simulation.hpp"

namespace clearjoint::app {

/// "clearjoint" or "simbody"; the names for a usage text.
inline constexpr std::string_view kDefaultEngine = "clearjoint";
inline constexpr const char* kEngineNames = "clearjoint (default), simbody";

/// The option that names the engine: the field path of an engine's refusal.
inline constexpr const char* kEngineOption = "--engine";

/// Empty when `engine` can run here; else why not, as require_engine's message
/// ("--engine = 'bogus': unknown engine; ...", "... built without Simbody ...").
std::string engine_unavailable(std::string_view engine);
/// Throw ValidationError, field path "--engine", unless `engine` can run here.
void require_engine(std::string_view engine);

/// Throw what running `model` with `engine` would throw for a model feature the engine does not
/// support (clearjoint::simbody::UnsupportedFeature, naming it), before any output folder exists.
/// Builds the model in that engine (cheap beside a run); nothing for the default engine.
void check_model_for_engine(std::string_view engine, const dynamics::ModelDescription& model);

/// Run `run`'s model with `engine` and write the tables `run.tables()` plans to `output` (CSV
/// files, an HDF5 file, memory), with the rows of every output.decimation-th report time and of
/// the last, and commit it: run.run() for the default engine (once per run), Simbody's
/// integration of the same model otherwise (`run` is then not run). Throws
/// require_engine's ValidationError for an engine that cannot run here, and what the engine
/// throws (a model feature the Simbody route does not support:
/// clearjoint::simbody::UnsupportedFeature, a ModelError, a SolverError).
dynamics::SimulationSummary simulate_with_engine(std::string_view engine, dynamics::SimulationRun& run,
                                                 dynamics::SimulationOutput& output,
                                                 const dynamics::ProgressCallback& progress);

/// A run planned before any output exists, ready to write its tables to a sink.
using PlannedRun =
    std::function<dynamics::SimulationSummary(dynamics::SimulationOutput&, const dynamics::ProgressCallback&)>;

/// Plan `model`'s run with `engine`: a compliant model (solver.method "dormand_prince") as
/// dynamics::SimulationRun (the default engine or Simbody, check_model_for_engine), a
/// "moreau_jean" one as clearjoint::nonsmooth::MoreauJeanRun (the default engine only; the same
/// tables, docs/nonsmooth.md). Throws what planning throws (ModelError, SolverError,
/// a ValidationError naming --engine for an engine that cannot run the model, a ModelError naming
/// solver.method when this program was built without Siconos).
PlannedRun plan_run(std::string_view engine, const dynamics::ModelDescription& model,
                    const dynamics::RunOptions& options);

}  // namespace clearjoint::app
