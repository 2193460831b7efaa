// SPDX-License-Identifier: BSD-3-Clause
// clearjoint simulate MODEL --out DIR: run a multibody model file and write CSV time series
// (dynamics/include/clearjoint/dynamics/simulation.hpp lists the files and columns).

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/dynamics/output_folder.hpp"
#include "clearjoint/dynamics/run_size.hpp"
#include "clearjoint/dynamics/simulation.hpp"
#include "json/bounded_json.hpp"
#include "commands.hpp"

namespace clearjoint::app {

namespace {

constexpr const char* kUsage =
    "usage: clearjoint simulate MODEL.json --out DIR [--force] [--allow-large]\n"
    "  Integrates the model and writes body_<name>.csv, energy.csv, reactions.csv and, for force\n"
    "  elements with outputs (clearance joints), force_<name>.csv into DIR.\n"
    "  DIR appears as one unit when the run succeeds (written in a staging folder next to it,\n"
    "  then renamed); a failed or killed run leaves an earlier DIR as it was.\n"
    "  --force        replace DIR if it exists and is not empty (otherwise an error)\n"
    "  --allow-large  run beyond the size guard (1000 s simulated, 1e7 report times, 4 GB of\n"
    "                 CSV files)\n"
    "  Progress goes to standard error: a bar on a terminal, else a line every 10 s.\n"
    "  Model file format: model.schema.json (JSON Schema 2020-12, in docs/schema/ and installed\n"
    "  in share/clearjoint/schema/); examples in models/; docs/dynamics.md.\n";

/// Progress on standard error: a one-line bar redrawn in place on a terminal; elsewhere (a log,
/// a batch job) one line every kLogInterval, so that a long run is seen to be alive without
/// filling the log.
class ProgressReport {
 public:
  ProgressReport() : terminal_(::isatty(::fileno(stderr)) == 1), start_(Clock::now()), last_log_(start_) {}
  void update(double fraction) {
    if (terminal_) {
      draw_bar(fraction);
      return;
    }
    const auto now = Clock::now();
    if (now - last_log_ < kLogInterval) return;
    last_log_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    std::fprintf(stderr, "clearjoint simulate: %.1f%% of the simulated time after %.0f s\n", 100.0 * fraction,
                 elapsed);
    std::fflush(stderr);
  }
  void finish() {
    if (terminal_ && last_percent_ >= 0) std::fputc('\n', stderr);
  }

 private:
  using Clock = std::chrono::steady_clock;
  /// Between two log lines when standard error is not a terminal.
  static constexpr std::chrono::seconds kLogInterval{10};

  void draw_bar(double fraction) {
    const int percent = static_cast<int>(fraction * 100.0);
    if (percent == last_percent_) return;
    last_percent_ = percent;
    constexpr int kWidth = 40;
    const int filled = percent * kWidth / 100;
    std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "########################################",
                 kWidth - filled, "", percent);
    std::fflush(stderr);
  }

  bool terminal_;
  Clock::time_point start_, last_log_;
  int last_percent_ = -1;
};

}  // namespace

int run_simulate(Arguments args) {
  const char* model_path = nullptr;
  const char* out_dir = nullptr;
  bool force = false;
  bool allow_large = false;
  for (size_t k = 0; k < args.size(); ++k) {
    if (std::strcmp(args[k], "--help") == 0 || std::strcmp(args[k], "-h") == 0) {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (std::strcmp(args[k], "--out") == 0) {
      if (k + 1 == args.size()) {
        std::fprintf(stderr, "clearjoint simulate: --out needs a directory\n%s", kUsage);
        return 2;
      }
      out_dir = args[++k];
    } else if (std::strcmp(args[k], "--force") == 0) {
      force = true;
    } else if (std::strcmp(args[k], "--allow-large") == 0) {
      allow_large = true;
    } else if (model_path == nullptr && args[k][0] != '-') {
      model_path = args[k];
    } else {
      std::fprintf(stderr, "clearjoint simulate: unexpected argument '%s'\n%s", args[k], kUsage);
      return 2;
    }
  }
  if (model_path == nullptr || out_dir == nullptr) {
    std::fputs(kUsage, stderr);
    return 2;
  }

  const dynamics::ModelDescription model = dynamics::read_model_file(model_path);
  // Every check that can fail before the run: the size guard builds the model (all model
  // checks), and simulate() checks the output file names before integrating.
  const dynamics::RunSize size = dynamics::estimate_run_size(model);
  if (!allow_large) dynamics::check_run_size(size);
  dynamics::OutputFolder folder(out_dir, force);
  ProgressReport bar;
  dynamics::SimulationSummary summary;
  try {
    summary = dynamics::simulate(model, folder.staging(), [&bar](double f) { bar.update(f); });
    folder.publish();
  } catch (...) {
    bar.finish();
    throw;
  }
  bar.finish();
  std::printf("model: %s\n", json::excerpt(model.name, 200).c_str());
  std::printf("simulated %g s to %g s: %ld steps, %ld right-hand-side evaluations, steps %.3g s to %.3g s\n",
              model.solver.start_time, model.solver.end_time, summary.integration.steps,
              summary.integration.derivative_calls, summary.integration.smallest_step,
              summary.integration.largest_step);
  if (summary.integration.restarts > 0) {
    std::printf("stepper restarts after impact-memory changes: %ld\n", summary.integration.restarts);
    std::printf("contact onsets located inside steps: %ld (%ld dense-output probes)\n",
                summary.integration.located_onsets, summary.integration.onset_probes);
  }
  if (summary.integration.failed_attempts > 0) {
    std::printf("steps retried shorter after a trial stage could not be evaluated: %ld\n",
                summary.integration.failed_attempts);
  }
  for (const std::string& line : summary.element_statistics) std::printf("%s\n", line.c_str());
  std::printf("initial conditions: %d Newton iterations, |Phi| = %.3g, |Phi_q v + Phi_t| = %.3g\n",
              summary.initial_conditions.iterations, summary.initial_conditions.position_residual,
              summary.initial_conditions.velocity_residual);
  std::printf("mechanical energy: E0 = %.9g J, max |E - E0| = %.3g J\n", summary.initial_energy,
              summary.max_energy_change);
  std::printf("constraint violation: max |Phi| = %.3g, max |dPhi/dt| = %.3g; max ||p| - 1| = %.3g\n",
              summary.max_position_violation, summary.max_velocity_violation,
              summary.max_euler_norm_drift);
  std::printf("results: %s\n", out_dir);
  return 0;
}

}  // namespace clearjoint::app
