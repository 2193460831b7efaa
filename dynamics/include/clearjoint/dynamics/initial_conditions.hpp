// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Consistent initial conditions (paper Sec. 6: "the remaining coordinates and velocities are
/// calculated in such a way that the kinematic constraints are fulfilled"): Newton-Raphson on the
/// position constraints with chosen coordinates held, then the velocity equations.

#include <span>
#include <vector>

#include "clearjoint/dynamics/multibody_system.hpp"

namespace clearjoint::dynamics {

/// One of the six world-frame coordinates of a body: position x, y, z or small rotation about the
/// world x, y, z axes (index 0..5); for velocities: velocity x, y, z or angular velocity x, y, z.
struct HeldCoordinate {
  BodyIndex body = 0;
  int component = 0;
};

/// A held velocity component and its prescribed value (world frame, m/s or rad/s).
struct HeldVelocity {
  BodyIndex body = 0;
  int component = 0;
  double value = 0.0;
};

struct InitialConditionOptions {
  /// Stop when max |Phi| is below this. Phi mixes metres and dimensionless direction cosines;
  /// 1e-13 is ~1000 ulps of metre-scale coordinates, well inside the 1e-8 drift budget.
  double position_tolerance = 1e-13;
  /// Stop when max |Phi_q v + Phi_t| / (1 + max |v|) is below this (relative velocity residual).
  double velocity_tolerance = 1e-12;
  int max_iterations = 50;
};

struct InitialConditionReport {
  int iterations = 0;
  double position_residual = 0.0;  ///< max |Phi| after the correction
  double velocity_residual = 0.0;  ///< max |Phi_q v + Phi_t| after the correction
};

/// Correct `states` (at time `time`) in place: the smallest change, in the least-squares sense,
/// of the non-held world coordinates that satisfies Phi = 0, then set the held velocities and make
/// the smallest change of the others that satisfies Phi_q v = -Phi_t.
/// Throws SolverError if the constraints are redundant at the start, the Newton iteration does
/// not converge (inconsistent constraints or over-held coordinates: names the worst equation),
/// or the held velocities contradict the constraints.
InitialConditionReport make_consistent(MultibodySystem& system, double time,
                                       std::vector<BodyState>& states,
                                       std::span<const HeldCoordinate> held_positions,
                                       std::span<const HeldVelocity> held_velocities,
                                       const InitialConditionOptions& options = {});

}  // namespace clearjoint::dynamics
