// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A model file run in Simbody (`clearjoint simulate --engine simbody`): the mechanism built by
/// SimbodyModel, integrated by Simbody's Runge-Kutta-Merson integrator at accuracy
/// solver.relative_tolerance from the initial state clearjoint makes consistent, and reported at
/// the same times in the same tables, with the same columns, as dynamics::simulate(). What the
/// columns hold in Simbody's terms:
///   body_<name>   Simbody's body pose, velocity and acceleration; e0..e3 from its rotation, with
///                 the sign kept continuous from the model's initial Euler parameters
///   energy        System::calcKineticEnergy and calcPotentialEnergy (gravity, springs, contact
///                 elastic energy); position_violation and velocity_violation are the largest
///                 |QErr| and |UErr| (loop constraints only); euler_norm_drift the largest
///                 ||q| - 1| of the quaternions of Ball and Free mobilizers
///   reactions     a tree joint's mobilizer reaction (calcMobilizerReactionForces), a loop
///                 joint's constraint force, on the body dynamics::joint_reaction reports,
///                 moment about its joint point
///   force_<name>  clearjoint's own ClearanceRevoluteJoint::record_outputs at Simbody's state
/// solver.absolute_tolerance is not used: Simbody weighs errors by its own unit scales.

#include <filesystem>

#include "clearjoint/dynamics/simulation.hpp"

namespace clearjoint::simbody {

/// Run `model` in Simbody and send the tables to `output`. The summary's integration counters
/// are Simbody's: steps taken, realisations of the dynamics (derivative_calls), events handled
/// (located_onsets); the smallest and largest steps are those of the steps seen between reports.
/// Throws UnsupportedFeature (model_in_simbody.hpp), dynamics::ModelError or SolverError.
dynamics::SimulationSummary simulate_in_simbody(const dynamics::ModelDescription& model,
                                                dynamics::SimulationOutput& output,
                                                const dynamics::ProgressCallback& progress = {});

/// The same, writing the CSV files into `output_directory` (created if missing, after the model
/// has been built).
dynamics::SimulationSummary simulate_in_simbody(const dynamics::ModelDescription& model,
                                                const std::filesystem::path& output_directory,
                                                const dynamics::ProgressCallback& progress = {});

}  // namespace clearjoint::simbody
