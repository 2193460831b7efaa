// SPDX-License-Identifier: BSD-3-Clause
// The stall rule of a fixed-step engine (clearjoint/mujoco/wall_time_guard.hpp) on a fake clock:
// a run whose rest is projected beyond kMaxProjectedStallWindows stall wall times is stopped at
// the end of a window, naming the projection; nothing is judged inside a window.

#include <gtest/gtest.h>

#include <string>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/mujoco/wall_time_guard.hpp"

namespace clearjoint::mujoco {
namespace {

constexpr double kStallWallTime = 60.0;  // [s], the default (dynamics::kStallWallTime)

struct FakeClock {
  double now = 1000.0;
  WallTimeGuard::Clock clock() {
    return [this] { return now; };
  }
};

/// The SolverError message of check(time), or "" when the run goes on.
std::string stop_message(WallTimeGuard& guard, double time) {
  try {
    guard.check(time);
  } catch (const dynamics::SolverError& e) {
    return e.what();
  }
  return "";
}

TEST(MujocoWallTimeGuard, StopsARunProjectedBeyondAnHourAtTheEndOfTheFirstWindow) {
  // 1 s simulated; 0.004 s done in the first 30 s window: the remaining 0.996 s take
  // 0.996 / (0.004 / 30) = 7470 s, over the hour (60 stall wall times of 60 s).
  FakeClock fake;
  WallTimeGuard guard(0.0, 1.0, kStallWallTime, fake.clock());
  fake.now += 29.9;
  EXPECT_EQ(stop_message(guard, 0.004), "") << "judged inside the window";
  fake.now += 0.1;
  const std::string message = stop_message(guard, 0.004);
  EXPECT_NE(message.find("MuJoCo run stopped at t = 0.004 s"), std::string::npos) << message;
  EXPECT_NE(message.find("would take about 7.47e+03 s (2.08 h) of wall time, more than 3.6e+03 s (1 h)"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("--allow-large"), std::string::npos) << message;
}

TEST(MujocoWallTimeGuard, LetsARunProjectedUnderTheLimitGoOnWindowAfterWindow) {
  // 0.01 s per 30 s window: the remaining 0.99 s take 2970 s, under 3600 s.
  FakeClock fake;
  WallTimeGuard guard(0.0, 1.0, kStallWallTime, fake.clock());
  double time = 0.0;
  for (int window = 0; window < 5; ++window) {
    fake.now += 30.0;
    time += 0.01;
    EXPECT_EQ(stop_message(guard, time), "") << "window " << window;
  }
}

TEST(MujocoWallTimeGuard, JudgesEveryWindowOnItsOwnRate) {
  // A fast first window, then one ten times slower: stopped at the second.
  FakeClock fake;
  WallTimeGuard guard(0.0, 1.0, kStallWallTime, fake.clock());
  fake.now += 30.0;
  EXPECT_EQ(stop_message(guard, 0.1), "");  // 0.9 s left at 0.1 s per 30 s: 270 s
  fake.now += 30.0;
  const std::string message = stop_message(guard, 0.101);  // 0.899 s left at 0.001 s per 30 s
  EXPECT_NE(message.find("would take about 2.7e+04 s (7.49 h)"), std::string::npos) << message;
}

TEST(MujocoWallTimeGuard, StopsAWindowWithoutProgress) {
  FakeClock fake;
  WallTimeGuard guard(0.0, 1.0, kStallWallTime, fake.clock());
  fake.now += 31.0;
  const std::string message = stop_message(guard, 0.0);
  EXPECT_NE(message.find("would take about inf s"), std::string::npos) << message;
}

TEST(MujocoWallTimeGuard, ScalesTheWindowAndTheLimitWithTheStallWallTime) {
  // A stall wall time of 0.2 s: windows of 0.1 s and a limit of 12 s. 1 ms in 0.1 s leaves
  // 0.999 s for 99.9 s of wall time.
  FakeClock fake;
  WallTimeGuard guard(0.0, 1.0, 0.2, fake.clock());
  fake.now += 0.1;
  const std::string message = stop_message(guard, 0.001);
  EXPECT_NE(message.find("more than 12 s"), std::string::npos) << message;
  EXPECT_NE(message.find("about 99.9 s"), std::string::npos) << message;
}

}  // namespace
}  // namespace clearjoint::mujoco
