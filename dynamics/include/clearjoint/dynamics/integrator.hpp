// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Time integration with Boost.Odeint's controlled, dense-output Dormand-Prince 5(4) stepper (the
/// method behind MATLAB's ode45, which the paper uses), reporting at a fixed step by interpolation.

#include <functional>
#include <span>
#include <vector>

#include "clearjoint/dynamics/multibody_system.hpp"

namespace clearjoint::dynamics {

struct IntegratorSettings {
  double start_time = 0.0;
  double end_time = 1.0;             ///< paper: 1 s
  double report_step = 1e-5;         ///< paper Table 2: 1e-5 s
  double relative_tolerance = 1e-7;  ///< paper Table 2: 1e-7
  double absolute_tolerance = 1e-7;  ///< paper Table 2: 1e-7
  double initial_step = 1e-6;        ///< first trial step [s]; the controller adapts it at once
  /// A proposed step below this [s] means the solution is no longer resolvable (a singularity or
  /// a blow-up): the run stops. 1e-14 s is ~100 ulps of t at t = 1 s; below it t + dt == t soon.
  double minimum_step = 1e-14;
  long max_steps = 100'000'000;  ///< guard against a hang with a tiny but legal step
};

/// Throw ModelError naming the field unless the settings are usable (finite, ordered, positive).
void validate(const IntegratorSettings& settings);

struct IntegrationStatistics {
  long steps = 0;              ///< accepted steps
  long derivative_calls = 0;   ///< right-hand-side evaluations
  double smallest_step = 0.0;  ///< of the accepted steps [s]
  double largest_step = 0.0;
  /// Restarts of the stepper after a force element changed its extra state (impact memory).
  long restarts = 0;
  /// Steps abandoned because the right-hand side failed (SolverError) at one of their trial
  /// stages, and retried with a quarter of the step.
  long failed_attempts = 0;
};

/// Called at start_time and at every report time up to end_time with the interpolated state.
using Observer = std::function<void(double time, std::span<const double> state)>;

/// Integrate y from start_time to end_time; on return y is the state at end_time.
/// After every accepted step (and at the start) the force elements may change their extra state
/// (MultibodySystem::update_extra_states); the stepper then restarts from the changed state.
/// Trial stages and rejected steps never reach that hook.
/// A right-hand side that throws SolverError at a trial stage rejects that step: it is retried
/// with a quarter of the step size; only a failure that persists below minimum_step stops the run.
/// Throws SolverError if the step collapses, max_steps is exceeded, the state stops being finite,
/// or the right-hand side fails (e.g. singular constraints); the message gives the time.
IntegrationStatistics integrate(MultibodySystem& system, std::vector<double>& y,
                                const IntegratorSettings& settings, const Observer& observer);

}  // namespace clearjoint::dynamics
