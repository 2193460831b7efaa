// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A model file run in Simbody (`clearjoint simulate --engine simbody`): the mechanism built by
/// SimbodyModel, integrated by Simbody's Runge-Kutta-Merson integrator at accuracy
/// solver.relative_tolerance from the initial state clearjoint makes consistent, and written as
/// the tables clearjoint's own run plans (dynamics::SimulationRun::tables(): the same names and
/// columns) at the same report times, to the same sinks (dynamics::SimulationOutput: CSV files,
/// an HDF5 file, memory), with the rows of every output.decimation-th report time and of the
/// last. What the columns hold in Simbody's terms:
///   body_<name>   Simbody's body pose, velocity and acceleration; e0..e3 from its rotation, with
///                 the sign kept continuous from the model's initial Euler parameters
///   energy        System::calcKineticEnergy and calcPotentialEnergy (gravity, springs, contact
///                 elastic energy); position_violation and velocity_violation are the largest
///                 |QErr| and |UErr| (loop constraints only); euler_norm_drift the largest
///                 ||q| - 1| of the quaternions of Ball and Free mobilizers
///   reactions     a tree joint's mobilizer reaction (calcMobilizerReactionForces), a loop
///                 joint's constraint force, on the body dynamics::joint_reaction reports,
///                 moment about its joint point
///   force_<name>  clearjoint's own ClearanceRevoluteJoint::record_outputs at Simbody's state,
///                 with a lubricated joint's film.work integrated by Simbody
///                 (ClearanceRevoluteForce)
/// solver.absolute_tolerance is not used: Simbody weighs errors by its own unit scales.

#include <filesystem>

#include "clearjoint/dynamics/simulation.hpp"

namespace clearjoint::simbody {

/// Run `run`'s model in Simbody and send the tables `run.tables()` plans to `output` (declared
/// in the plan's order), committing it after the last row; `run` itself is not run. The summary's
/// extremes see every report time; its integration counters are Simbody's: steps taken,
/// realisations of the dynamics (derivative_calls), impacts recorded (located_onsets); the
/// smallest and largest steps are those of the steps seen between reports. Throws
/// UnsupportedFeature (model_in_simbody.hpp), dynamics::ModelError, SolverError or what `output`
/// throws, and std::logic_error if the Simbody route's tables ever drift from the plan.
dynamics::SimulationSummary simulate_in_simbody(const dynamics::SimulationRun& run,
                                                dynamics::SimulationOutput& output,
                                                const dynamics::ProgressCallback& progress = {});

/// The same for `model`, planned as dynamics::simulate(model, output) plans it (no size guard).
dynamics::SimulationSummary simulate_in_simbody(const dynamics::ModelDescription& model,
                                                dynamics::SimulationOutput& output,
                                                const dynamics::ProgressCallback& progress = {});

/// The same, writing the CSV files into `output_directory` (created if missing, after the model
/// has been built).
dynamics::SimulationSummary simulate_in_simbody(const dynamics::ModelDescription& model,
                                                const std::filesystem::path& output_directory,
                                                const dynamics::ProgressCallback& progress = {});

}  // namespace clearjoint::simbody
