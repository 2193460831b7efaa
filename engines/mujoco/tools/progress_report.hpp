// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// clearjoint-mujoco's progress on standard error, as `clearjoint simulate` reports its own
/// (apps/clearjoint/simulate_command.cpp): a one-line bar redrawn in place on a terminal;
/// elsewhere (a log, a batch job) a line "clearjoint-mujoco: 12.5% of the simulated time after
/// 10 s" every `log_interval` seconds, so that a long run is seen to be alive without filling the
/// log.

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace clearjoint::mujoco_tool {

class ProgressReport {
 public:
  explicit ProgressReport(double log_interval)
      : terminal_(::isatty(::fileno(stderr)) == 1),
        log_interval_(log_interval),
        start_(Clock::now()),
        last_log_(start_) {}

  /// The run has done `fraction` (0 to 1) of its simulated time.
  void update(double fraction) {
    if (terminal_) {
      draw_bar(fraction);
      return;
    }
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - last_log_).count() < log_interval_) return;
    last_log_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    std::fprintf(stderr, "clearjoint-mujoco: %.1f%% of the simulated time after %.0f s\n", 100.0 * fraction,
                 elapsed);
    std::fflush(stderr);
  }
  /// Ends the bar's line on a terminal.
  void finish() {
    if (terminal_ && last_percent_ >= 0) std::fputc('\n', stderr);
    last_percent_ = -1;
  }

 private:
  using Clock = std::chrono::steady_clock;

  void draw_bar(double fraction) {
    const int percent = static_cast<int>(fraction * 100.0);
    if (percent == last_percent_) return;
    last_percent_ = percent;
    constexpr int kWidth = 40;
    const int filled = percent * kWidth / 100;
    std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "########################################", kWidth - filled,
                 "", percent);
    std::fflush(stderr);
  }

  bool terminal_;
  double log_interval_;
  Clock::time_point start_, last_log_;
  int last_percent_ = -1;
};

}  // namespace clearjoint::mujoco_tool
