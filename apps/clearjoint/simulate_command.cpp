// SPDX-License-Identifier: BSD-3-Clause
// clearjoint simulate MODEL --out DIR: run a multibody model file and write CSV time series
// (dynamics/include/clearjoint/dynamics/simulation.hpp lists the files and columns).

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <cstring>
#include <string>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/dynamics/model_overrides.hpp"
#include "clearjoint/dynamics/simulation.hpp"
#include "clearjoint/engines/engine_choice.hpp"
#include "clearjoint/json_input/bounded_json.hpp"
#include "run_folder.hpp"
#include "commands.hpp"
#ifdef CLEARJOINT_WITH_NONSMOOTH
#include "clearjoint/nonsmooth/moreau_jean_run.hpp"
#endif

namespace clearjoint::app {

using engines::kDefaultEngine;
using engines::PlannedRun;
/// The option that names the engine: the field path of an engine's refusal.
constexpr std::string_view kEngineOption = "--engine";

namespace {

constexpr const char* kUsage =
    "usage: clearjoint simulate MODEL.json --out DIR [--format csv|hdf5] [--report-step S]\n"
    "                           [--decimation K] [--end-time T] [--set PATH=VALUE ...] [--engine NAME]\n"
    "                           [--force] [--allow-large] [--plot] [--write-fclib DIR [--fclib-count N]]\n"
    "  Integrates the model and writes into DIR its tables (csv: body_<name>.csv, energy.csv,\n"
    "  reactions.csv and, for force elements with outputs (clearance joints), force_<name>.csv;\n"
    "  hdf5: run.h5 with one dataset per table), model.json (the model run) and summary.json.\n"
    "  DIR appears as one unit when the run succeeds (written in a staging folder next to it,\n"
    "  then renamed); a failed or killed run leaves an earlier DIR as it was.\n"
    "  --format       csv (default) or hdf5\n"
    "  --report-step  the report interval [s], in place of the model's solver.report_step\n"
    "  --decimation   write every K-th report time (and the last), in place of output.decimation\n"
    "  --end-time     the simulated end time [s], in place of the model's solver.end_time\n"
    "  --set          PATH=VALUE: one value of the model in place of the file's, validated like\n"
    "                 the file; PATH dotted (solver.end_time, bodies[1].mass) or a JSON pointer\n"
    "                 (/bodies/1/mass); VALUE JSON (1e-3, true, [0, 0, -9.81], \"text\"), or a\n"
    "                 word beginning with a letter, taken as a string (model=hertz); repeatable,\n"
    "                 one field once; model.json records the model run, summary.json the values set\n"
    "  --engine       the integrating engine: clearjoint (default) or simbody; the same tables,\n"
    "                 columns, formats and decimation (docs/engines.md)\n"
    "  --write-fclib  DIR: with solver.method \"moreau_jean\", also write the contact problems of\n"
    "                 the first N steps with an active contact, with the solution found, as FCLIB\n"
    "                 HDF5 files DIR/step_<k>.hdf5 (docs/nonsmooth.md); DIR is created if absent\n"
    "  --fclib-count  N, the number of problems --write-fclib writes (default 100)\n"
    "  --force        replace DIR if it is an earlier result (otherwise an error)\n"
    "  --plot         draw the run's figures into DIR/figures afterwards (clearjoint plot)\n"
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

int (*plot_published_run)(const char* run_dir) = nullptr;

namespace {

/// The largest --fclib-count (nonsmooth::kMaxFclibProblems when the non-smooth integrator is built).
long nonsmooth_fclib_max() {
#ifdef CLEARJOINT_WITH_NONSMOOTH
  return nonsmooth::kMaxFclibProblems;
#else
  return 1;
#endif
}

/// The options of one `clearjoint simulate` call.
struct SimulateArguments {
  const char* model_path = nullptr;
  const char* out_dir = nullptr;
  bool force = false;
  bool allow_large = false;
  bool plot = false;
  std::string format = "csv";
  std::string engine = std::string(kDefaultEngine);
  const char* fclib_dir = nullptr;  ///< --write-fclib
  std::optional<long> fclib_count;  ///< --fclib-count
  /// --report-step, --decimation, --end-time and --set, in the order given: written into the
  /// model's JSON before it is read (model_overrides.hpp), so that they are validated as the
  /// file's values are.
  dynamics::ModelOverrides overrides;
};

/// A number as JSON text in its shortest round-trip form (what model.json then holds).
std::string json_number(double value) { return nlohmann::json(value).dump(); }

/// A number option's value, or a usage error naming the option.
bool read_number_option(const char* option, const char* text, double& out) {
  char* end = nullptr;
  out = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(out)) {
    std::fprintf(stderr, "clearjoint simulate: %s = '%s': must be a number\n%s", option, text, kUsage);
    return false;
  }
  return true;
}

/// Parses `args`; returns an exit status when the call ends here (help, usage error), else -1.
/// An option the library's check refused: its message and the usage; exit status 2.
int refused_option(const ValidationError& error) {
  std::fprintf(stderr, "clearjoint simulate: %s\n%s", error.what(), kUsage);
  return 2;
}

int parse(Arguments args, SimulateArguments& a) {
  for (size_t k = 0; k < args.size(); ++k) {
    const char* arg = args[k];
    auto value = [&](const char* what) -> const char* {
      if (k + 1 == args.size()) {
        std::fprintf(stderr, "clearjoint simulate: %s needs %s\n%s", arg, what, kUsage);
        return nullptr;
      }
      return args[++k];
    };
    if (std::strcmp(arg, "--help") == 0 || std::strcmp(arg, "-h") == 0) {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (std::strcmp(arg, "--out") == 0) {
      if ((a.out_dir = value("a directory")) == nullptr) return 2;
    } else if (std::strcmp(arg, "--format") == 0) {
      const char* format = value("csv or hdf5");
      if (format == nullptr) return 2;
      a.format = format;
      try {
        dynamics::run_format(a.format, "--format");  // the one check of a format, Python's too
      } catch (const ValidationError& e) {
        return refused_option(e);
      }
    } else if (std::strcmp(arg, "--report-step") == 0) {
      const char* text = value("a time step in seconds");
      double step = 0.0;
      if (text == nullptr || !read_number_option("--report-step", text, step)) return 2;
      a.overrides.push_back({"solver.report_step", json_number(step), std::string("--report-step ") + text});
    } else if (std::strcmp(arg, "--end-time") == 0) {
      const char* text = value("a time in seconds");
      double end = 0.0;
      if (text == nullptr || !read_number_option("--end-time", text, end)) return 2;
      a.overrides.push_back({"solver.end_time", json_number(end), std::string("--end-time ") + text});
    } else if (std::strcmp(arg, "--set") == 0) {
      const char* text = value("PATH=VALUE");
      if (text == nullptr) return 2;
      try {
        a.overrides.push_back(dynamics::parse_override_assignment(text, std::string("--set ") + text));
      } catch (const ValidationError& e) {
        return refused_option(e);
      }
    } else if (std::strcmp(arg, "--decimation") == 0) {
      const char* text = value("a whole number");
      double decimation = 0.0;
      if (text == nullptr || !read_number_option("--decimation", text, decimation)) return 2;
      if (!(decimation >= 1.0 && decimation <= dynamics::kMaxDecimation && decimation == std::floor(decimation))) {
        std::fprintf(stderr, "clearjoint simulate: --decimation = '%s': must be a whole number in [1, 1e9]\n", text);
        return 2;
      }
      a.overrides.push_back({"output.decimation", std::to_string(static_cast<long>(decimation)),
                             std::string("--decimation ") + text});
    } else if (std::strcmp(arg, "--engine") == 0) {
      const char* engine = value("an engine name");
      if (engine == nullptr) return 2;
      a.engine = engine;
      if (const std::string why = engines::engine_unavailable(a.engine, kEngineOption); !why.empty()) {
        std::fprintf(stderr, "clearjoint simulate: %s\n", why.c_str());
        return 2;
      }
    } else if (std::strcmp(arg, "--write-fclib") == 0) {
      if ((a.fclib_dir = value("a directory")) == nullptr) return 2;
    } else if (std::strcmp(arg, "--fclib-count") == 0) {
      const char* text = value("a whole number");
      double count = 0.0;
      if (text == nullptr || !read_number_option("--fclib-count", text, count)) return 2;
      if (!(count >= 1.0 && count <= static_cast<double>(nonsmooth_fclib_max()) && count == std::floor(count))) {
        std::fprintf(stderr, "clearjoint simulate: --fclib-count = '%s': must be a whole number in [1, %ld]\n", text,
                     nonsmooth_fclib_max());
        return 2;
      }
      a.fclib_count = static_cast<long>(count);
    } else if (std::strcmp(arg, "--force") == 0) {
      a.force = true;
    } else if (std::strcmp(arg, "--allow-large") == 0) {
      a.allow_large = true;
    } else if (std::strcmp(arg, "--plot") == 0) {
      a.plot = true;
    } else if (a.model_path == nullptr && arg[0] != '-') {
      a.model_path = arg;
    } else {
      std::fprintf(stderr, "clearjoint simulate: unexpected argument '%s'\n%s", arg, kUsage);
      return 2;
    }
  }
  if (a.model_path == nullptr || a.out_dir == nullptr) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  if (a.fclib_count && a.fclib_dir == nullptr) {
    std::fprintf(stderr, "clearjoint simulate: --fclib-count needs --write-fclib DIR\n%s", kUsage);
    return 2;
  }
  if (a.plot && plot_published_run == nullptr) {
    std::fputs("clearjoint simulate: --plot needs the clearjoint Python package (clearjoint plot), which this "
               "program was built without\n", stderr);
    return 2;
  }
  return -1;
}

/// A Moreau-Jean run that also writes its contact problems (--write-fclib): planned as plan_run
/// plans one, the FCLIB folder checked before the run folder exists.
PlannedRun plan_fclib_run(const SimulateArguments& a, const dynamics::ModelDescription& model,
                          const dynamics::RunOptions& options) {
  if (model.solver_method != dynamics::SolverMethod::moreau_jean) {
    throw dynamics::ModelError("--write-fclib " + std::string(a.fclib_dir) +
                               ": needs solver.method = \"moreau_jean\" (a compliant run has no contact "
                               "problems; docs/nonsmooth.md)");
  }
#ifdef CLEARJOINT_WITH_NONSMOOTH
  if (a.engine != kDefaultEngine) {
    return engines::plan_run(a.engine, kEngineOption, model, options);  // refuses, naming --engine
  }
  auto run = std::make_shared<nonsmooth::MoreauJeanRun>(model, options);
  run->write_fclib({a.fclib_dir, a.fclib_count.value_or(nonsmooth::kDefaultFclibProblems)});
  return [run](dynamics::SimulationOutput& output, const dynamics::ProgressCallback& progress) {
    return run->run(output, progress);
  };
#else
  return engines::plan_run(a.engine, kEngineOption, model, options);  // refuses: built without the non-smooth integrator
#endif
}

}  // namespace

int run_simulate(Arguments args) {
  SimulateArguments a;
  if (const int status = parse(args, a); status >= 0) return status;

  // The text is read once, the overrides written into it, and that text parsed (validated as a
  // file holding those values) and written as the run's model.json: the model as run.
  std::string model_text = dynamics::read_model_text(a.model_path);
  if (!a.overrides.empty()) model_text = dynamics::apply_overrides(model_text, a.model_path, a.overrides);
  const dynamics::ModelDescription model = dynamics::parse_model(model_text, a.model_path);
  // Every check that can fail before the run, before the output folder exists: the model is
  // built once, its tables planned (name collisions) and the size guard applied to that plan.
  // Another engine refuses the features it does not support, naming them, before the folder exists.
  // solver.method "moreau_jean" plans the non-smooth run (docs/nonsmooth.md).
  const dynamics::RunOptions run_options{.allow_large = a.allow_large};
  const PlannedRun run = a.fclib_dir != nullptr ? plan_fclib_run(a, model, run_options)
                                                : engines::plan_run(a.engine, kEngineOption, model, run_options);
  const dynamics::RunFolderOptions options{dynamics::run_format(a.format), a.force, a.overrides};
  ProgressReport bar;
  dynamics::SimulationSummary summary;
  try {
    const auto progress = [&bar](double f) { bar.update(f); };
    summary = dynamics::write_run_folder([&](dynamics::SimulationOutput& output) { return run(output, progress); },
                                         model_text, a.out_dir, options);
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
  std::printf("results: %s\n", a.out_dir);
  std::fflush(stdout);
  if (a.plot) return plot_published_run(a.out_dir);
  return 0;
}

}  // namespace clearjoint::app
