// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The stall rule, shared by every engine (clearjoint's integrator, the Simbody route): a run
/// whose step size has collapsed is stopped within IntegratorSettings::stall_wall_time of wall
/// time (a minute, kStallWallTime), whatever its end time and its step budget.
///
/// The rule. Wall time is cut into windows of stall_wall_time / 2, each starting where the last
/// ended. When a window has passed (seen at the first accepted step after it), the guard takes
/// the simulated time the run advanced in it, dt, and the steps it accepted, n, and the mean step
/// h = dt / n. The step has collapsed when h < kCollapsedStepFraction * (end_time - start_time):
/// at that step the whole run would need more than 1 / kCollapsedStepFraction steps. The run then
/// stops with SolverError naming h, the steps it would need and the progress made in the window.
/// A collapse that begins inside one window fills the next one entirely, so the run stops at most
/// stall_wall_time after its step collapsed. A run that is over within one window is never judged.

#include <functional>

#include "clearjoint/dynamics/integrator_settings.hpp"

namespace clearjoint::dynamics {

/// Below this mean step, as a fraction of the simulated span, the step has collapsed: the run
/// would need more than ten million steps. The paper's runs (1 s, relative tolerance 1e-7) take
/// well under a million steps, their impacts included; a run that starts far beyond a clearance
/// or holds a contact too stiff for the explicit stepper takes steps of 1e-10 s (1e-8 of a
/// 4 ms span, some fifty million steps and hours of wall time).
inline constexpr double kCollapsedStepFraction = 1e-7;

class StallGuard {
 public:
  /// Wall time in seconds from any fixed origin (a monotonic clock).
  using Clock = std::function<double()>;

  /// For a run over [settings.start_time, settings.end_time] judged on windows of
  /// settings.stall_wall_time / 2; `clock` defaults to std::chrono::steady_clock (tests pass a
  /// fake one). The first window starts now, at simulated time `time` with `steps` steps taken.
  StallGuard(const IntegratorSettings& settings, double time, long steps, Clock clock = {});

  /// After an accepted step: the run is at simulated time `time` with `steps` accepted steps in
  /// all. Throws SolverError (naming the engine as `engine` when not empty) if a window has ended
  /// with a collapsed step.
  void check(double time, long steps, const char* engine = "");

 private:
  double span_;
  double window_;
  Clock clock_;
  double window_start_wall_ = 0.0;
  double window_start_time_ = 0.0;
  long window_start_steps_ = 0;
};

}  // namespace clearjoint::dynamics
