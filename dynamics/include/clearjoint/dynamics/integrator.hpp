// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Time integration with Boost.Odeint's controlled, dense-output Dormand-Prince 5(4) stepper (the
/// method behind MATLAB's ode45, which the paper uses), reporting at a fixed step by interpolation.

#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "clearjoint/dynamics/integrator_settings.hpp"
#include "clearjoint/dynamics/multibody_system.hpp"

namespace clearjoint::dynamics {

/// Steps between two projections of the step budget (IntegratorSettings::max_steps). Long enough
/// that one impact's short steps (hundreds to a few thousand) do not make the projection, short
/// enough that a collapsed run stops within seconds (some 20,000 steps a second).
inline constexpr long kStallWindowSteps = 50'000;

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
  /// Event onsets located inside accepted steps, and the right-hand-side-free probes of the
  /// dense output (each one kinematics update and one begins_event check) that bracketed them.
  long located_onsets = 0;
  long onset_probes = 0;
};

/// Called at start_time and at every report time up to end_time with the interpolated state.
using Observer = std::function<void(double time, std::span<const double> state)>;
/// Called after every accepted step with its end time (may be empty): cheap, so that a caller can
/// look at a clock there, report progress between report times, or throw to stop the run.
using StepMonitor = std::function<void(double time)>;

/// The integration of integrate() below, one accepted step at a time, for callers that drive a
/// run (Simulator: controls, co-simulation, their own event logic). The constructor makes the
/// start's discrete update and reports start_time; each step() takes one accepted step, reports
/// the report times inside it, and makes the step's discrete updates, exactly as integrate()
/// does. Throws as integrate() does.
class Integrator {
 public:
  Integrator(MultibodySystem& system, std::span<const double> initial_state, const IntegratorSettings& settings,
             const Observer& observer = {});
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;
  ~Integrator();

  /// Time and state of the last accepted step (after its discrete updates).
  double time() const;
  std::span<const double> state() const;
  /// The step the controller proposes next [s].
  double next_step() const;
  /// Every report time up to end_time has been reported.
  bool finished() const;
  const IntegrationStatistics& statistics() const;
  const IntegratorSettings& settings() const;
  /// The state at the last report time (the initial state before any).
  std::span<const double> last_reported_state() const;

  void step(const Observer& observer = {}, const StepMonitor& monitor = {});
  /// Continue from `state` at time(): the force elements' discrete update runs on it and the
  /// stepper restarts with `step` (the controller's proposal when 0).
  void restart(std::span<const double> state, double step = 0.0);
  /// The right-hand side changed between steps (a load applied or cleared): restart from the
  /// current state, whose stored derivative (the stepper's first-same-as-last stage) is stale.
  void right_hand_side_changed();
  /// Make the next step at most `step` long (a restart from the current state; nothing when the
  /// proposal is shorter already).
  void limit_next_step(double step);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Integrate y from start_time to end_time; on return y is the state at end_time.
/// After every accepted step (and at the start) the force elements may change their extra state
/// (MultibodySystem::update_extra_states); the stepper then restarts from the changed state.
/// Trial stages and rejected steps never reach that hook. When an accepted step ends with a new
/// event (MultibodySystem::begins_event), settings.onset says where it is recorded: the earliest
/// instant of the step where begins_event turns true is bracketed by bisection on the stepper's
/// dense output to sqrt(relative_tolerance) times the step, and the hook is called at the
/// bracket's upper end (the first probed instant with the event present).
/// A right-hand side that throws SolverError at a trial stage rejects that step: it is retried
/// with a quarter of the step size; only a failure that persists below minimum_step stops the run.
/// Throws SolverError if the step collapses (below minimum_step, or so small that the projected
/// steps exceed max_steps), max_steps is exceeded, the state stops being finite, or the
/// right-hand side fails (e.g. singular constraints); the message gives the time.
IntegrationStatistics integrate(MultibodySystem& system, std::vector<double>& y,
                                const IntegratorSettings& settings, const Observer& observer,
                                const StepMonitor& monitor = {});

}  // namespace clearjoint::dynamics
