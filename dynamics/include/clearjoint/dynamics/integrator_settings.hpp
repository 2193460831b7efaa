// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The integrator's settings (integrator.hpp), plain data: a model description holds them
/// without depending on the integrator or the system it integrates.

namespace clearjoint::dynamics {

/// What the integrator does when an accepted step ends with a new event (ForceElement::
/// begins_event: a contact onset, whose impact velocity delta_dot(-) of eq. 28 is remembered).
enum class OnsetHandling {
  /// Record at the end of the accepted step, where the event was seen (no location): the
  /// recorded delta_dot(-) is the approach speed after part of a step in contact.
  step_end,
  /// Locate the onset on the step's dense output, record there, and restart the stepper from
  /// that instant: the whole contact is integrated with the recorded value.
  restart_at_onset,
  /// Locate the onset and record there, but keep the state at the end of the step (integrated
  /// with the provisional value from the onset to the step's end).
  record_at_onset,
};

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
  /// Most accepted steps. Also a budget checked ahead: every kStallWindowSteps steps the run
  /// projects how many steps the rest of it needs at the mean step of that window, and stops
  /// (SolverError naming the step size) when the projection exceeds this, long before the steps
  /// are spent: a model that starts deep beyond a clearance takes steps of 1e-10 s and would run
  /// for hours (docs/dynamics.md, "When a run stops").
  long max_steps = 100'000'000;
  /// record_at_onset, chosen by measurement (docs/dynamics.md, "Contact onset"): both located
  /// variants give the exact restitution law to 1e-4 and the tight-tolerance impact speeds to
  /// 1 %, but restarting puts the interpolant's error at a non-smooth instant into the state
  /// (an elastic journal's energy drift over 57 impacts at 1e-11: 4.3e-6 against 2.1e-7).
  OnsetHandling onset = OnsetHandling::record_at_onset;
};

/// Throw ModelError naming the field unless the settings are usable (finite, ordered, positive).
void validate(const IntegratorSettings& settings);

}  // namespace clearjoint::dynamics
