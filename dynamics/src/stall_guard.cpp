// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/stall_guard.hpp"

#include <chrono>
#include <cstdio>
#include <string>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

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

}  // namespace

StallGuard::StallGuard(const IntegratorSettings& settings, double time, long steps, Clock clock)
    : span_(settings.end_time - settings.start_time),
      window_(0.5 * settings.stall_wall_time),
      clock_(clock ? std::move(clock) : Clock(steady_seconds)),
      window_start_wall_(clock_()),
      window_start_time_(time),
      window_start_steps_(steps) {}

void StallGuard::check(double time, long steps, const char* engine) {
  const double now = clock_();
  if (!(now - window_start_wall_ >= window_)) return;
  const double advanced = time - window_start_time_;
  const long taken = steps - window_start_steps_;
  const double wall = now - window_start_wall_;
  window_start_wall_ = now;
  window_start_time_ = time;
  window_start_steps_ = steps;
  if (taken <= 0) return;  // no step seen in the window: nothing to judge
  const double mean_step = advanced / static_cast<double>(taken);
  if (mean_step >= kCollapsedStepFraction * span_) return;
  const std::string who = engine[0] != '\0' ? std::string(engine) + " " : std::string();
  throw SolverError(who + "integration stopped at t = " + format_number(time) +
                    ": the step size has collapsed to a mean of " + three_digits(mean_step) + " s over the last " +
                    std::to_string(taken) + " steps (" + three_digits(wall) + " s of wall time, " +
                    three_digits(100.0 * advanced / span_) + " % of the run); at that step the run needs about " +
                    three_digits(span_ / mean_step) + " steps, more than " +
                    three_digits(1.0 / kCollapsedStepFraction) +
                    " (the stall rule, docs/dynamics.md). Often a contact is too stiff to resolve or "
                    "the tolerances are too tight: check the force laws and solver.relative_tolerance");
}

}  // namespace clearjoint::dynamics
