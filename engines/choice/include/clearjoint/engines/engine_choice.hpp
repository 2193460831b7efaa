// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The engine that integrates a run: clearjoint's own (the default) or Simbody (engines/simbody,
// docs/engines.md), both writing the tables of one plan (dynamics::SimulationRun) to one sink
// (dynamics::SimulationOutput), so that the format, the decimation and the columns are the same
// whichever engine runs; a solver.method "moreau_jean" model as clearjoint::nonsmooth's run. The
// one check of an engine's name and the one plan of a run for every front-end that runs models
// (the program's `simulate --engine NAME`, Python's `simulate(engine=NAME)`): each passes the
// name of its own field ("--engine", "engine") for the messages.

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "clearjoint/dynamics/simulation.hpp"

namespace clearjoint::engines {

/// clearjoint's own engine, the default of every front-end.
inline constexpr std::string_view kDefaultEngine = "clearjoint";

/// The engines this build can run, the default first ("clearjoint", then "simbody" when the
/// Simbody adapter is built).
std::vector<std::string_view> available_engines();

/// Empty when `engine` can run here; else why not, as require_engine's message
/// ("<field> = 'bogus': unknown engine; the engines of this build are ...", "... built without
/// Simbody ...").
std::string engine_unavailable(std::string_view engine, std::string_view field);
/// Throw ValidationError, field path `field`, unless `engine` can run here.
void require_engine(std::string_view engine, std::string_view field);

/// Throw what running `model` with `engine` would throw for a model feature the engine does not
/// support (clearjoint::simbody::UnsupportedFeature, naming it), before any output folder exists.
/// Builds the model in that engine (cheap beside a run); nothing for the default engine.
void check_model_for_engine(std::string_view engine, std::string_view field, const dynamics::ModelDescription& model);

/// Run `run`'s model with `engine` and write the tables `run.tables()` plans to `output` (CSV
/// files, an HDF5 file, memory), with the rows of every output.decimation-th report time and of
/// the last, and commit it: run.run() for the default engine (once per run), Simbody's
/// integration of the same model otherwise (`run` is then not run). Throws
/// require_engine's ValidationError for an engine that cannot run here, and what the engine
/// throws (a model feature the Simbody route does not support:
/// clearjoint::simbody::UnsupportedFeature, a ModelError, a SolverError).
dynamics::SimulationSummary simulate_with_engine(std::string_view engine, std::string_view field,
                                                 dynamics::SimulationRun& run, dynamics::SimulationOutput& output,
                                                 const dynamics::ProgressCallback& progress);

/// A run planned before any output exists, ready to write its tables to a sink.
using PlannedRun =
    std::function<dynamics::SimulationSummary(dynamics::SimulationOutput&, const dynamics::ProgressCallback&)>;

/// Plan `model`'s run with `engine`: a compliant model (solver.method "dormand_prince") as
/// dynamics::SimulationRun (the default engine or Simbody, check_model_for_engine), a
/// "moreau_jean" one as clearjoint::nonsmooth::MoreauJeanRun (the default engine only; the same
/// tables, docs/nonsmooth.md). Throws what planning throws (ModelError, SolverError,
/// a ValidationError naming `field` for an engine that cannot run the model, a ModelError naming
/// solver.method when this build has no Siconos).
PlannedRun plan_run(std::string_view engine, std::string_view field, const dynamics::ModelDescription& model,
                    const dynamics::RunOptions& options);

}  // namespace clearjoint::engines
