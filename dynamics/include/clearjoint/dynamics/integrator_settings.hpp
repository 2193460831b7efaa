// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The integrator's settings (integrator.hpp), plain data: a model description holds them
/// without depending on the integrator or the system it integrates.

namespace clearjoint::dynamics {

/// Largest solver.relative_tolerance: an error of 10 % per step already leaves nothing of the
/// trajectory to compare (the paper uses 1e-7); Simbody's Integrator::setAccuracy aborts at 1.
inline constexpr double kMaxRelativeTolerance = 0.1;
/// Smallest solver.relative_tolerance: about 45 ulps of double precision (epsilon 2.2e-16). The
/// error estimate of a step is itself rounded to a few ulps, so a tighter tolerance is never met
/// and the step shrinks until the run stalls.
inline constexpr double kMinRelativeTolerance = 1e-14;
/// Default IntegratorSettings::stall_wall_time [s]: no run goes on for more than a minute of wall
/// time after its step size has collapsed (stall_guard.hpp).
inline constexpr double kStallWallTime = 60.0;

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
  /// Wall time [s] within which a run whose step has collapsed is stopped (StallGuard,
  /// stall_guard.hpp), in every engine. Not read from model files; tests shorten it.
  double stall_wall_time = kStallWallTime;
};

/// Throw ModelError naming the field and its value unless the settings are usable: times finite
/// and ordered; report_step, the tolerances, initial_step and minimum_step positive;
/// relative_tolerance in [kMinRelativeTolerance, kMaxRelativeTolerance]; minimum_step shorter
/// than the span (end_time - start_time) and the report step, and not longer than initial_step
/// (the first step would already count as collapsed); max_steps in [1, 1e15]; stall_wall_time
/// positive. The error's field path is the field's ("solver.max_steps").
/// Every engine reads the settings only after this check (Simbody aborts on some of them).
void validate(const IntegratorSettings& settings);

}  // namespace clearjoint::dynamics
