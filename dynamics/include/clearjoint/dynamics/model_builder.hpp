// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// From a ModelDescription to a MultibodySystem with consistent initial conditions.

#include <memory>
#include <vector>

#include "clearjoint/dynamics/initial_conditions.hpp"
#include "clearjoint/dynamics/model_description.hpp"
#include "clearjoint/dynamics/multibody_system.hpp"

namespace clearjoint::dynamics {

struct BuiltModel {
  std::unique_ptr<MultibodySystem> system;
  std::vector<BodyState> initial_states;  ///< after make_consistent()
  InitialConditionReport initial_conditions;
  std::vector<double> initial_state;      ///< packed y at solver.start_time
};

/// Resolve body names, build joints' equations from the model's initial poses, the force
/// elements (gravity first when non-zero), and make the initial conditions consistent.
/// Throws ModelError (bad names or values, naming the field) or SolverError (inconsistent or
/// redundant constraints).
BuiltModel build_model(const ModelDescription& model);

/// A model's consistent initial conditions, from its mechanism alone.
struct ConsistentStart {
  std::vector<BodyState> initial_states;  ///< after make_consistent(), as build_model's
  InitialConditionReport initial_conditions;
};

/// The initial conditions build_model makes consistent, without building any force element: for
/// an engine that builds its own forces (the Simbody route) and starts from clearjoint's state.
/// Checks what the mechanism needs and the model's names: bodies, joints, held coordinates,
/// outputs, each force's name and the bodies it names, gravity; a force's own constants are
/// checked where the force is built (its constructor, or the engine's). Throws as build_model.
ConsistentStart consistent_start(const ModelDescription& model);

/// Index 0..5 of a held component name ("x".."rz" for positions, "vx".."wz" for velocities).
int held_component_index(std::string_view name, bool velocity, std::string_view field);

}  // namespace clearjoint::dynamics
