// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The stall rule (dynamics/stall_guard.hpp) for a fixed-step engine. MuJoCo's step never
/// collapses: it is the model's <option timestep>. What runs away instead is a run far longer
/// than meant (a timestep or a duration off by an exponent: 5e-9 s for 5e-7 s is a hundred times
/// the steps), whose wall time is known only once its steps are timed. The guard times them on
/// the stall rule's windows and stops a run whose projected wall time is out of reach, so that,
/// as in every engine, no run goes on for more than the stall wall time before it is judged.
///
/// The rule. Wall time is cut into windows of stall_wall_time / 2, each starting where the last
/// ended (StallGuard's windows). When a window has passed (seen at the first step after it), the
/// guard takes the simulated time the run advanced in it and the wall time the window took, and
/// projects the wall time the rest of the run needs at that rate. The run stops (SolverError
/// naming the rate and the projection) when the projection exceeds kMaxProjectedStallWindows
/// stall wall times (an hour at the default minute). A run that is over within one window is
/// never judged; a run whose rate drops later (contacts that cost more) is judged again on every
/// window.

#include <functional>

namespace clearjoint::mujoco {

/// The most wall time a run's remainder may be projected to need, in stall wall times: 60, an
/// hour at dynamics::kStallWallTime. The example's 1 s run (2e6 RK4 steps) takes about 20 s on
/// the 2-core development machine, so an hour admits models 180 times as costly, or runs as
/// long, and stops a run of days within its first windows. Counted in stall wall times so that
/// a test that shortens the window shortens the limit with it.
inline constexpr double kMaxProjectedStallWindows = 60.0;

class WallTimeGuard {
 public:
  /// Wall time in seconds from any fixed origin (a monotonic clock).
  using Clock = std::function<double()>;

  /// For a run over [start_time, end_time] of simulated time, judged on windows of
  /// stall_wall_time / 2 (dynamics::IntegratorSettings::stall_wall_time, > 0); `clock` defaults
  /// to std::chrono::steady_clock (tests pass a fake one). The first window starts now, at
  /// simulated time `start_time`.
  WallTimeGuard(double start_time, double end_time, double stall_wall_time, Clock clock = {});

  /// After a step: the run is at simulated time `time`. Throws dynamics::SolverError if a window
  /// has ended and, at the rate of that window, the rest of the run needs more than
  /// kMaxProjectedStallWindows * stall_wall_time of wall time.
  void check(double time);

 private:
  double end_time_;
  double stall_wall_time_;
  double window_;
  Clock clock_;
  double window_start_wall_ = 0.0;
  double window_start_time_ = 0.0;
};

}  // namespace clearjoint::mujoco
