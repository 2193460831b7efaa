// SPDX-License-Identifier: BSD-3-Clause
// clearjoint-mujoco MODEL.xml --out DIR [--duration T] [--report-step DT] [--force] [--allow-large]:
// run an MJCF model with clearance joints (clearjoint/mujoco/clearance_joints.hpp) in MuJoCo and
// write a run folder as `clearjoint simulate` writes one (the body, energy and force tables of
// run_tables.hpp, summary.json, and the model as model.xml), published as one unit
// (dynamics/output_folder.hpp); progress on standard error; the stall rule of a fixed-step
// engine (clearjoint/mujoco/wall_time_guard.hpp).

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "clearjoint/dynamics/csv_directory.hpp"
#include <nlohmann/json.hpp>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/integrator_settings.hpp"
#include "clearjoint/dynamics/output_folder.hpp"
#include "clearjoint/dynamics/run_size.hpp"
#include "clearjoint/dynamics/simulation.hpp"
#include "clearjoint/mujoco/clearance_joints.hpp"
#include "clearjoint/mujoco/wall_time_guard.hpp"
#include "progress_report.hpp"
#include "run_tables.hpp"

namespace {

constexpr const char* kUsage =
    "usage: clearjoint-mujoco MODEL.xml --out DIR [--duration T] [--report-step DT] [--force]\n"
    "                         [--allow-large]\n"
    "  Runs the MJCF model in MuJoCo (its own timestep and integrator) from its first keyframe\n"
    "  (or qpos0 at rest) for T seconds (default 1) and writes a run folder DIR: body_<name>.csv\n"
    "  for each body, energy.csv, force_<name>.csv for each clearance joint (one row every DT\n"
    "  seconds, default 1e-5, rounded to whole steps), summary.json and the model as model.xml.\n"
    "  DIR appears as one unit when the run succeeds, as with `clearjoint simulate`\n"
    "  (docs/command-line.md, \"Output folder\").\n"
    "  --force        replace DIR if it is an earlier result (otherwise an error)\n"
    "  --allow-large  run beyond the size guard (1000 s simulated, 1e7 report times, 4 GB of\n"
    "                 CSV files) and the stall rule (a run projected to need more than an hour)\n"
    "  Progress goes to standard error: a bar on a terminal, else a line every 10 s. A run whose\n"
    "  rest is projected, after 30 s, to need more than an hour of wall time is stopped.\n"
    "  Clearance joints are declared in the model's <custom> section: docs/engines.md.\n";

/// The environment variable that shortens the stall wall time (dynamics::kStallWallTime, a
/// minute), as the dynamics tests shorten IntegratorSettings::stall_wall_time: for the program's
/// tests, which cannot wait a minute. The progress lines and the stall rule scale with it.
constexpr const char* kStallWallTimeVariable = "CLEARJOINT_STALL_WALL_TIME";
/// Progress lines per stall wall time when standard error is not a terminal: one every 10 s at
/// the default minute, as `clearjoint simulate` prints them, and two before the stall rule first
/// judges the run (after half the stall wall time).
constexpr double kProgressLinesPerStallWallTime = 6.0;

/// Most MuJoCo steps a run counts (a step index is a long): the integrator's own bound on report
/// times (dynamics/src/integrator.cpp, kMaxReportCount), which --allow-large does not lift.
constexpr double kMaxStepCount = 1e15;
/// Most characters of an argument quoted in a message: the JSON readers' limit
/// (clearjoint/json_input/bounded_json.hpp, kMaxQuotedValue).
constexpr size_t kQuotedCharacters = 60;

/// The shortest text that reads back as `value` ("5e-07"), for the numbers quoted in messages.
std::string shortest(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

struct MjModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct MjDataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

/// A bad command line: exit status 2 with the usage.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// MuJoCo's default handlers write MUJOCO_LOG.TXT into the current folder, and its error
/// handler then waits for Enter and exits; these report on standard error instead, and an error
/// ends the run through main's handler (the output folder's staging is removed on the way).
void report_mujoco_warning(const char* message) {
  std::fprintf(stderr, "clearjoint-mujoco: MuJoCo warning: %s\n", message);
}
[[noreturn]] void throw_mujoco_error(const char* message) {
  throw std::runtime_error(std::string("MuJoCo error: ") + message);
}

struct Arguments {
  const char* model_path = nullptr;
  const char* out_dir = nullptr;
  double duration = 1.0;
  double report_step = 1e-5;
  std::string duration_text = "1";  ///< as given, for messages
  std::string report_step_text = "1e-5";
  bool force = false;
  bool allow_large = false;
};

/// A duration option's value: a finite number of seconds above 0, or a UsageError naming it.
double read_seconds(const char* option, const char* text) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(value) || !(value > 0.0)) {
    throw UsageError(std::string(option) + " = '" + std::string(text).substr(0, kQuotedCharacters) +
                     "': must be a finite number of seconds above 0");
  }
  return value;
}

/// The stall wall time: kStallWallTimeVariable's value when set, else a minute.
double stall_wall_time() {
  const char* text = std::getenv(kStallWallTimeVariable);
  if (text == nullptr) return clearjoint::dynamics::kStallWallTime;
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(value) || !(value > 0.0)) {
    throw std::runtime_error(std::string(kStallWallTimeVariable) + " = '" +
                             std::string(text).substr(0, kQuotedCharacters) +
                             "': must be a finite number of seconds above 0");
  }
  return value;
}

Arguments parse(int argc, char** argv) {
  Arguments a;
  std::vector<std::string> seen;
  bool report_step_given = false;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg.starts_with("--") && arg != "--help") {
      for (const std::string& earlier : seen) {
        if (earlier == arg) throw UsageError(arg + ": given twice");
      }
      seen.push_back(arg);
    }
    const auto value = [&]() -> const char* {
      if (k + 1 == argc) throw UsageError(arg + ": needs a value");
      return argv[++k];
    };
    if (arg == "--out") {
      a.out_dir = value();
    } else if (arg == "--duration") {
      a.duration_text = std::string(value()).substr(0, kQuotedCharacters);
      a.duration = read_seconds("--duration", a.duration_text.c_str());
    } else if (arg == "--report-step") {
      a.report_step_text = std::string(value()).substr(0, kQuotedCharacters);
      report_step_given = true;
      a.report_step = read_seconds("--report-step", a.report_step_text.c_str());
    } else if (arg == "--force") {
      a.force = true;
    } else if (arg == "--allow-large") {
      a.allow_large = true;
    } else if (a.model_path == nullptr && !arg.starts_with("-")) {
      a.model_path = argv[k];
    } else {
      throw UsageError("unexpected argument '" + arg.substr(0, kQuotedCharacters) + "'");
    }
  }
  if (a.model_path == nullptr) throw UsageError("no model file given");
  if (a.out_dir == nullptr) throw UsageError("--out DIR is required");
  if (!report_step_given) {
    a.report_step = std::min(a.report_step, a.duration);  // the default, for a shorter run
  } else if (a.report_step > a.duration) {
    throw UsageError("--report-step = " + a.report_step_text + " s: longer than --duration = " + a.duration_text +
                     " s");
  }
  return a;
}

std::string lift_hint() {
  return " (a guard against a slip of the exponent; pass --allow-large to run it anyway)";
}

/// The run's steps at the model's timestep and its steps between two rows, after the checks
/// `clearjoint simulate` applies to a run's size (dynamics/run_size.hpp); std::runtime_error
/// naming the option otherwise.
struct Schedule {
  long steps = 0;
  long steps_per_report = 1;
};

Schedule schedule(const Arguments& a, double timestep, const std::vector<clearjoint::dynamics::TablePlan>& tables) {
    if (!a.allow_large && a.duration > clearjoint::dynamics::kMaxSimulatedSpan) {
    throw std::runtime_error("--duration = " + a.duration_text + " s: longer than " +
                     shortest(clearjoint::dynamics::kMaxSimulatedSpan) + " s" + lift_hint());
  }
  const double steps = std::round(a.duration / timestep);
  if (steps < 1.0) {
    throw std::runtime_error("--duration = " + a.duration_text + " s: shorter than the model's timestep " +
                     shortest(timestep) + " s (<option timestep>)");
  }
  if (!(steps <= kMaxStepCount)) {
    throw std::runtime_error("--duration = " + a.duration_text + " s: " + shortest(steps) + " steps of " +
                     shortest(timestep) + " s, more than " + shortest(kMaxStepCount) +
                     ", the most this program counts");
  }
  const double per_report = std::max(1.0, std::round(a.report_step / timestep));
  clearjoint::dynamics::IntegratorSettings solver;
  solver.start_time = 0.0;
  solver.end_time = steps * timestep;
  solver.report_step = per_report * timestep;
  const clearjoint::dynamics::RunSize size = clearjoint::dynamics::run_size(solver, 1, tables);
  if (!a.allow_large && size.report_rows > clearjoint::dynamics::kMaxReportRows) {
    throw std::runtime_error("--report-step = " + a.report_step_text + " s: " + shortest(size.report_rows) +
                     " report times, more than " + shortest(clearjoint::dynamics::kMaxReportRows) + lift_hint());
  }
  if (!a.allow_large && size.output_bytes > clearjoint::dynamics::kMaxOutputBytes) {
    throw std::runtime_error("--duration and --report-step: about " + shortest(std::round(size.output_bytes / 1e6)) +
                     " MB of CSV files, more than " + shortest(clearjoint::dynamics::kMaxOutputBytes / 1e6) +
                     " MB" + lift_hint());
  }
  return {static_cast<long>(steps), static_cast<long>(per_report)};
}

/// MuJoCo resets the state when it finds a bad number in it, and carries on: rows after that
/// would be a different run's, so the run stops instead.
void refuse_reset_state(const mjData* data) {
  for (const auto& [warning, what] : {std::pair{mjWARN_BADQPOS, "qpos"}, std::pair{mjWARN_BADQVEL, "qvel"},
                                      std::pair{mjWARN_BADQACC, "qacc"}}) {
    if (data->warning[warning].number > 0) {
      throw std::runtime_error("MuJoCo found a bad number (NaN, infinity or beyond 1e10) in " + std::string(what) +
                               " by t = " + shortest(data->time) +
                               " s and reset the state; no result is written (a smaller timestep, or other "
                               "initial velocities?)");
    }
  }
}

int run(int argc, char** argv) {
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--help") == 0) {
      std::fputs(kUsage, stdout);
      return 0;
    }
  }
  const Arguments a = parse(argc, argv);
  const double stall_time = stall_wall_time();
  mju_user_warning = report_mujoco_warning;
  mju_user_error = throw_mujoco_error;

  char error[1000] = "";
  std::unique_ptr<mjModel, MjModelDeleter> model(mj_loadXML(a.model_path, nullptr, error, sizeof error));
  if (!model) {
    std::fprintf(stderr, "clearjoint-mujoco: %s: %s\n", a.model_path, error);
    return 1;
  }
  if (error[0] != '\0') std::fprintf(stderr, "clearjoint-mujoco: %s: MuJoCo warning: %s\n", a.model_path, error);
  clearjoint::mujoco::ClearanceJoints clearance(model.get());
  if (clearance.count() == 0) {
    std::fprintf(stderr, "clearjoint-mujoco: %s declares no clearance joint (<text name=\"clearance:NAME\">)\n",
                 a.model_path);
    return 1;
  }
  clearjoint::mujoco_tool::RunTables tables(model.get(), clearance);
  const Schedule plan = schedule(a, model->opt.timestep, tables.tables());
  std::unique_ptr<mjData, MjDataDeleter> data(mj_makeData(model.get()));
  if (model->nkey > 0) mj_resetDataKeyframe(model.get(), data.get(), 0);
  clearance.install();
  // The initial state gets the checks mj_step makes on every state.
  mj_checkPos(model.get(), data.get());
  mj_checkVel(model.get(), data.get());
  mj_forward(model.get(), data.get());
  mj_checkAcc(model.get(), data.get());
  refuse_reset_state(data.get());
  clearance.after_step(data.get());

  // Every check above is made before the output folder is claimed: a refused run creates nothing.
  clearjoint::dynamics::OutputFolder folder(a.out_dir, a.force);

  clearjoint::dynamics::CsvDirectory files(folder.staging());
  tables.declare(files);
  const double start_time = data->time;
  const double end_time = start_time + static_cast<double>(plan.steps) * model->opt.timestep;
  std::unique_ptr<clearjoint::mujoco::WallTimeGuard> guard;
  if (!a.allow_large) {
    guard = std::make_unique<clearjoint::mujoco::WallTimeGuard>(start_time, end_time, stall_time);
  }
  clearjoint::mujoco_tool::ProgressReport progress(stall_time / kProgressLinesPerStallWallTime);

  tables.write(data.get(), files);
  for (long s = 1; s <= plan.steps; ++s) {
    mj_step(model.get(), data.get());
    refuse_reset_state(data.get());
    clearance.after_step(data.get());
    if (s % plan.steps_per_report == 0 || s == plan.steps) tables.write(data.get(), files);
    progress.update(static_cast<double>(s) / static_cast<double>(plan.steps));
    if (guard) guard->check(data->time);
  }
  progress.finish();
  files.commit();

  nlohmann::ordered_json summary;
  summary["engine"] = "mujoco";
  summary["steps"] = plan.steps;
  summary["smallest_step"] = model->opt.timestep;
  summary["largest_step"] = model->opt.timestep;
  summary["initial_energy"] = tables.initial_energy();
  summary["max_energy_change"] = tables.max_energy_change();
  summary["element_statistics"] = nlohmann::ordered_json::array();
  for (int k = 0; k < clearance.count(); ++k) {
    summary["element_statistics"].push_back(clearance.joint(k).statistics_text());
  }
  {
    std::ofstream out(folder.staging() / "summary.json");
    out << summary.dump(2) << "\n";
    if (!out.flush()) throw std::runtime_error("cannot write summary.json into " + folder.staging().string());
  }
  std::filesystem::copy_file(a.model_path, folder.staging() / "model.xml");
  folder.publish();
  for (int k = 0; k < clearance.count(); ++k) {
    std::printf("%s\n", clearance.joint(k).statistics_text().c_str());
  }
  std::printf("results: %s\n", a.out_dir);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "clearjoint-mujoco: %s\n%s", e.what(), kUsage);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clearjoint-mujoco: %s\n", e.what());
    return 1;
  }
}
