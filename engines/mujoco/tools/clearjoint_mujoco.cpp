// SPDX-License-Identifier: BSD-3-Clause
// clearjoint-mujoco MODEL.xml --out DIR [--duration T] [--report-step DT]: run an MJCF model with
// clearance joints (clearjoint/mujoco/clearance_joints.hpp) in MuJoCo and write, for each
// clearance joint, force_<name>.csv with the columns of `clearjoint simulate`'s force tables.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "clearjoint/mujoco/clearance_joints.hpp"
#include "clearjoint/dynamics/csv_directory.hpp"
#include "clearjoint/dynamics/simulation.hpp"

namespace {

constexpr const char* kUsage =
    "usage: clearjoint-mujoco MODEL.xml --out DIR [--duration T] [--report-step DT]\n"
    "  Runs the MJCF model in MuJoCo (its own timestep and integrator) from its first keyframe\n"
    "  (or qpos0 at rest) for T seconds (default 1) and writes force_<name>.csv for each\n"
    "  clearance joint into DIR, one row every DT seconds (default 1e-5, rounded to whole steps).\n"
    "  Clearance joints are declared in the model's <custom> section: docs/engines.md.\n";

struct MjModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct MjDataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

int run(int argc, char** argv) {
  const char* model_path = nullptr;
  const char* out_dir = nullptr;
  double duration = 1.0;
  double report_step = 1e-5;
  for (int k = 1; k < argc; ++k) {
    const bool has_value = k + 1 < argc;
    if (std::strcmp(argv[k], "--help") == 0) {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (std::strcmp(argv[k], "--out") == 0 && has_value) {
      out_dir = argv[++k];
    } else if (std::strcmp(argv[k], "--duration") == 0 && has_value) {
      duration = std::atof(argv[++k]);
    } else if (std::strcmp(argv[k], "--report-step") == 0 && has_value) {
      report_step = std::atof(argv[++k]);
    } else if (model_path == nullptr && argv[k][0] != '-') {
      model_path = argv[k];
    } else {
      std::fprintf(stderr, "clearjoint-mujoco: unexpected argument '%s'\n%s", argv[k], kUsage);
      return 2;
    }
  }
  if (model_path == nullptr || out_dir == nullptr || !(duration > 0.0) || !(report_step > 0.0)) {
    std::fputs(kUsage, stderr);
    return 2;
  }

  char error[1000] = "";
  std::unique_ptr<mjModel, MjModelDeleter> model(mj_loadXML(model_path, nullptr, error, sizeof error));
  if (!model) {
    std::fprintf(stderr, "clearjoint-mujoco: %s: %s\n", model_path, error);
    return 1;
  }
  clearjoint::mujoco::ClearanceJoints clearance(model.get());
  if (clearance.count() == 0) {
    std::fprintf(stderr, "clearjoint-mujoco: %s declares no clearance joint (<text name=\"clearance:NAME\">)\n",
                 model_path);
    return 1;
  }
  std::unique_ptr<mjData, MjDataDeleter> data(mj_makeData(model.get()));
  if (model->nkey > 0) mj_resetDataKeyframe(model.get(), data.get(), 0);
  clearance.install();
  mj_forward(model.get(), data.get());
  clearance.after_step(data.get());

  clearjoint::dynamics::CsvDirectory files(out_dir);
  std::vector<std::size_t> tables;
  for (int k = 0; k < clearance.count(); ++k) {
    std::vector<std::string> header = clearance.joint(k).output_columns();
    header.insert(header.begin(), "time");
    tables.push_back(files.add_table(
        clearjoint::dynamics::table_name("force_", clearance.joint(k).name()), header));
  }
  std::vector<double> row;
  auto report = [&] {
    for (int k = 0; k < clearance.count(); ++k) {
      row.assign(clearance.joint(k).output_columns().size() + 1, 0.0);
      row[0] = data->time;
      clearance.record_outputs(k, data.get(), std::span<double>(row).subspan(1));
      files.write_row(tables[k], row);
    }
  };

  const double dt = model->opt.timestep;
  const long steps = std::lround(duration / dt);
  const long steps_per_report = std::max(1L, std::lround(report_step / dt));
  report();
  for (long s = 1; s <= steps; ++s) {
    mj_step(model.get(), data.get());
    clearance.after_step(data.get());
    if (s % steps_per_report == 0 || s == steps) report();
  }
  files.commit();
  for (int k = 0; k < clearance.count(); ++k) {
    std::printf("%s\n", clearance.joint(k).statistics_text().c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clearjoint-mujoco: %s\n", e.what());
    return 1;
  }
}
