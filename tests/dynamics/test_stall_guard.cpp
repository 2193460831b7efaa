// SPDX-License-Identifier: BSD-3-Clause
// The stall rule (stall_guard.hpp) on a fake clock: a run is judged once per half of
// stall_wall_time of wall time, stopped when its mean step over the window is below
// kCollapsedStepFraction of its span, whatever its end time, and never judged before a window
// has passed.

#include <gtest/gtest.h>

#include <string>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/stall_guard.hpp"

namespace clearjoint::dynamics {
namespace {

/// A wall clock that a test moves by hand [s].
struct FakeClock {
  double now = 100.0;
  StallGuard::Clock clock() {
    return [this] { return now; };
  }
};

IntegratorSettings run_of(double span) {
  IntegratorSettings settings;
  settings.end_time = span;
  settings.stall_wall_time = 60.0;
  return settings;
}

TEST(StallGuard, StopsARunWhoseMeanStepOverAWindowIsBelowTheCollapsedFractionOfItsSpan) {
  // The tilted-axis slider-crank of 4 ms at 8e-11 s a step: some 5e7 steps, under max_steps.
  FakeClock wall;
  StallGuard guard(run_of(0.004), 0.0, 0, wall.clock());
  long steps = 0;
  double t = 0.0;
  try {
    for (; steps < 10'000'000; ++steps) {
      t += 8e-11;
      wall.now += 1e-4;  // 10,000 steps a second
      guard.check(t, steps + 1);
    }
    FAIL() << "the run went on";
  } catch (const SolverError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("the step size has collapsed to a mean of 8e-11 s"), std::string::npos) << message;
    EXPECT_NE(message.find("at that step the run needs about 5e+07 steps, more than 1e+07"), std::string::npos)
        << message;
  }
  // Judged after the first window, half of stall_wall_time: 30 s of wall time.
  EXPECT_NEAR(static_cast<double>(steps), 300000.0, 2.0);
}

TEST(StallGuard, LetsARunWhoseMeanStepIsAboveTheFractionGoOnForHours) {
  // A 1 s run at 1e-6 s a step (a million steps) at 2,000 steps a second: over eight minutes.
  FakeClock wall;
  StallGuard guard(run_of(1.0), 0.0, 0, wall.clock());
  double t = 0.0;
  for (long steps = 1; steps <= 1'000'000; ++steps) {
    t += 1e-6;
    wall.now += 5e-4;
    guard.check(t, steps);
  }
  SUCCEED();
}

TEST(StallGuard, StopsACollapseThatBeginsInsideAWindowWithinStallWallTime) {
  // Healthy steps for 45 s of wall time (inside the second window), then steps of 1e-12 s: the
  // second window's mean is still healthy, the third is all collapse and ends at 90 s.
  FakeClock wall;
  const double start = wall.now;
  StallGuard guard(run_of(1.0), 0.0, 0, wall.clock());
  double t = 0.0;
  long steps = 0;
  double collapsed_at = 0.0;
  try {
    for (;;) {
      const bool collapsed = wall.now - start >= 45.0;
      if (collapsed && collapsed_at == 0.0) collapsed_at = wall.now;
      t += collapsed ? 1e-12 : 1e-5;
      wall.now += 1e-3;
      guard.check(t, ++steps);
    }
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("collapsed"), std::string::npos) << e.what();
  }
  EXPECT_LE(wall.now - collapsed_at, 60.0 + 1e-6);
  EXPECT_GE(wall.now - collapsed_at, 30.0);
}

TEST(StallGuard, NeverJudgesARunShorterThanAWindow) {
  FakeClock wall;
  StallGuard guard(run_of(1.0), 0.0, 0, wall.clock());
  for (long steps = 1; steps <= 1000; ++steps) {
    wall.now += 0.029;  // 29 s in all, under the 30 s window
    guard.check(1e-15 * static_cast<double>(steps), steps);
  }
  SUCCEED();
}

TEST(StallGuard, StopsARunWhoseTimeNoLongerAdvances) {
  // Steps so small that t + dt == t: no progress at all.
  FakeClock wall;
  StallGuard guard(run_of(1.0), 0.5, 0, wall.clock());
  wall.now += 31.0;
  EXPECT_THROW(guard.check(0.5, 10), SolverError);
}

TEST(StallGuard, NamesTheEngineItGuards) {
  FakeClock wall;
  StallGuard guard(run_of(1.0), 0.0, 0, wall.clock());
  wall.now += 31.0;
  try {
    guard.check(1e-12, 10, "Simbody");
    FAIL() << "not stopped";
  } catch (const SolverError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("Simbody integration stopped at t = 9.9999999999999998e-13", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace clearjoint::dynamics
