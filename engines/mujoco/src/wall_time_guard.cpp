// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/mujoco/wall_time_guard.hpp"

#include <chrono>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::mujoco {

namespace {

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// `x` with three significant digits: a rate and a projection, not values to read back.
std::string three_digits(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

/// A wall time as a person reads it: "5.2e+03 s (1.4 h)".
std::string wall_time_text(double seconds) {
  if (seconds < 3600.0) return three_digits(seconds) + " s";
  const double hours = seconds / 3600.0;
  const std::string readable = hours < 48.0 ? three_digits(hours) + " h" : three_digits(hours / 24.0) + " days";
  return three_digits(seconds) + " s (" + readable + ")";
}

}  // namespace

WallTimeGuard::WallTimeGuard(double start_time, double end_time, double stall_wall_time, Clock clock)
    : end_time_(end_time),
      stall_wall_time_(stall_wall_time),
      window_(0.5 * stall_wall_time),
      clock_(clock ? std::move(clock) : Clock(steady_seconds)),
      window_start_wall_(clock_()),
      window_start_time_(start_time) {}

void WallTimeGuard::check(double time) {
  const double now = clock_();
  const double wall = now - window_start_wall_;
  if (!(wall >= window_)) return;
  const double advanced = time - window_start_time_;
  window_start_wall_ = now;
  window_start_time_ = time;
  const double limit = kMaxProjectedStallWindows * stall_wall_time_;
  const double rate = advanced / wall;  // simulated seconds per wall second
  const double projected = rate > 0.0 ? (end_time_ - time) / rate : std::numeric_limits<double>::infinity();
  if (projected <= limit) return;
  throw dynamics::SolverError(
      "MuJoCo run stopped at t = " + dynamics::format_shortest(time) + " s: it advanced " + three_digits(advanced) +
      " s of simulated time in the last " + three_digits(wall) + " s of wall time, so the remaining " +
      three_digits(end_time_ - time) + " s would take about " + wall_time_text(projected) +
      " of wall time, more than " + wall_time_text(limit) +
      " (the stall rule for a fixed-step engine, docs/engines.md). Check the model's <option timestep> and "
      "--duration; pass --allow-large to run it anyway");
}

}  // namespace clearjoint::mujoco
