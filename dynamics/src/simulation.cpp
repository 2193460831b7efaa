// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cmath>
#include <memory>

#include "clearjoint/dynamics/csv_writer.hpp"
#include "clearjoint/dynamics/csv_directory.hpp"
#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/force_recorder.hpp"
#include "clearjoint/dynamics/reaction_forces.hpp"
#include "clearjoint/dynamics/simulation_output.hpp"

namespace clearjoint::dynamics {

namespace {

std::vector<std::string> body_header() {
  return {"time", "x", "y", "z", "e0", "e1", "e2", "e3", "vx", "vy", "vz", "wx", "wy", "wz",
          "ax", "ay", "az", "alphax", "alphay", "alphaz"};
}

std::vector<std::string> reaction_header(const ConstraintSet& constraints) {
  std::vector<std::string> header{"time"};
  for (const JointEquations& joint : constraints.joints()) {
    for (const char* c : {"fx", "fy", "fz", "mx", "my", "mz"}) header.push_back(joint.name() + "." + c);
  }
  return header;
}

/// The tables of a run, each with what it is for ("output.bodies[1] \"crank\""), checked before
/// any is declared: no two share a name, also when compared without case (files that differ
/// only in case are one file on macOS and Windows).
class TableNames {
 public:
  TableNames() {
    add("energy", "energy.csv");
    add("reactions", "reactions.csv");
  }

  /// `name`; throws ModelError if an earlier table has it.
  std::string add(std::string name, const std::string& what) {
    std::string folded = name;
    for (char& c : folded) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const auto& [other_folded, other_what] : names_) {
      if (other_folded == folded) {
        throw ModelError(what + ": its output file " + name + ".csv has the name of " +
                         other_what + "'s (names are compared after characters other than "
                         "letters, digits, - and _ become _, and without case); rename one of them");
      }
    }
    names_.emplace_back(std::move(folded), what);
    return name;
  }

 private:
  std::vector<std::pair<std::string, std::string>> names_;  // folded name, what it is for
};

/// Wall-clock time between two progress calls made between report times.
constexpr std::chrono::milliseconds kProgressInterval{100};

}  // namespace

std::string table_name(std::string_view prefix, std::string_view name) {
  std::string table(prefix);
  for (char c : name) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '_';
    table.push_back(keep ? c : '_');
  }
  return table;
}

/// Where each table's rows come from: a body, a force element, or the system-wide tables.
struct SimulationRun::Sources {
  std::vector<BodyIndex> output_bodies;  ///< body_<name> tables, in plan order after the two fixed
  /// force_<name> tables: the element's index, its recorder, the recorder's column count.
  struct Element {
    std::size_t index = 0;
    const ForceRecorder* recorder = nullptr;
    std::size_t width = 0;
  };
  std::vector<Element> elements;
};

const ForceRecorder* recorded_by_run(const ForceElement& element, const ModelDescription& model) {
  const ForceRecorder* recorder = recorder_of(element);
  if (recorder == nullptr || recorder->output_columns().empty()) return nullptr;
  const auto& wanted = model.output_force_elements;
  const bool listed = model.output_all_force_elements ||
                      std::find(wanted.begin(), wanted.end(), element.name()) != wanted.end();
  return listed ? recorder : nullptr;
}

SimulationRun::SimulationRun(const ModelDescription& model, const RunOptions& options)
    : simulator_(std::make_unique<Simulator>(model)), sources_(std::make_unique<Sources>()) {
  const ModelDescription& m = simulator_->model();
  MultibodySystem& system = simulator_->system();
  // Every table name first, so that a collision stops the run before any table (file) exists.
  TableNames names;
  std::vector<std::string> body_names;
  for (size_t k = 0; k < m.output_bodies.size(); ++k) {
    body_names.push_back(names.add(table_name("body_", m.output_bodies[k]),
                                   "output.bodies[" + std::to_string(k) + "] \"" + m.output_bodies[k] + "\""));
  }
  std::vector<std::pair<Sources::Element, std::string>> element_names;
  for (size_t e = 0; e < system.force_elements().size(); ++e) {
    const ForceElement& element = *system.force_elements()[e];
    const ForceRecorder* recorder = recorded_by_run(element, m);
    if (recorder == nullptr) continue;
    element_names.emplace_back(Sources::Element{e, recorder, 0},
                               names.add(table_name("force_", element.name()),
                                         "force element \"" + std::string(element.name()) + "\""));
  }
  // The plan, in the order the tables are declared (and the files listed).
  for (size_t k = 0; k < m.output_bodies.size(); ++k) {
    sources_->output_bodies.push_back(system.body_index(m.output_bodies[k], "output.bodies"));
    tables_.push_back({body_names[k], body_header()});
  }
  tables_.push_back({"energy", {"time", "kinetic", "potential", "total", "position_violation",
                                "velocity_violation", "euler_norm_drift"}});
  tables_.push_back({"reactions", reaction_header(system.constraints())});
  for (auto& [e, name] : element_names) {
    std::vector<std::string> header = e.recorder->output_columns();
    e.width = header.size();
    sources_->elements.push_back(e);
    header.insert(header.begin(), "time");
    tables_.push_back({name, std::move(header)});
  }
  size_ = run_size(m.solver, m.output_decimation, tables_);
  if (!options.allow_large) check_run_size(size_);
}

SimulationRun::~SimulationRun() = default;

SimulationSummary SimulationRun::run(SimulationOutput& output, const ProgressCallback& progress) {
  if (ran_) throw std::logic_error("SimulationRun::run: a run is made once");
  ran_ = true;
  const ModelDescription& model = simulator_->model();
  const BuiltModel& built = simulator_->built();
  MultibodySystem& system = simulator_->system();

  std::vector<size_t> table_index;
  for (const TablePlan& table : tables_) table_index.push_back(output.add_table(table.name, table.header));
  const size_t bodies = sources_->output_bodies.size();
  const size_t energy_table = table_index[bodies];
  const size_t reaction_table = table_index[bodies + 1];

  SimulationSummary summary;
  summary.initial_conditions = built.initial_conditions;
  summary.initial_energy = system.kinetic_energy(built.initial_state) +
                           system.potential_energy(model.solver.start_time, built.initial_state);
  std::vector<double> rate(built.initial_state.size());
  std::vector<double> row;
  const int joint_count = static_cast<int>(system.constraints().joints().size());
  const double span = model.solver.end_time - model.solver.start_time;
  const long decimation = model.output_decimation;
  long report_index = 0;

  auto observe = [&](double t, std::span<const double> y) {
    // Rows of every decimation-th report time and of the last; the summary sees every one.
    const bool written = report_index % decimation == 0 || t == model.solver.end_time;
    ++report_index;
    system.derivative(t, y, rate);  // accelerations and multipliers at the reported state
    if (written) {
      const Eigen::VectorXd& a = system.accelerations();
      for (size_t k = 0; k < bodies; ++k) {
        const BodyIndex b = sources_->output_bodies[k];
        const BodyKinematics& kin = system.kinematics().body(b);
        const BodyState s = system.body_state(y, b);
        const Vector3 angular_acceleration_W = kin.rotation * a.segment<3>(6 * b + 3);
        row.assign({t});
        row.insert(row.end(), s.position_W.data(), s.position_W.data() + 3);
        row.insert(row.end(), s.euler_parameters.data(), s.euler_parameters.data() + 4);
        row.insert(row.end(), s.velocity_W.data(), s.velocity_W.data() + 3);
        row.insert(row.end(), kin.angular_velocity_W.data(), kin.angular_velocity_W.data() + 3);
        row.insert(row.end(), a.data() + 6 * b, a.data() + 6 * b + 3);
        row.insert(row.end(), angular_acceleration_W.data(), angular_acceleration_W.data() + 3);
        output.write_row(table_index[k], row);
      }

      row.assign({t});
      for (int j = 0; j < joint_count; ++j) {
        const JointReaction r = joint_reaction(system, j);
        row.insert(row.end(), r.force_W.data(), r.force_W.data() + 3);
        row.insert(row.end(), r.moment_W.data(), r.moment_W.data() + 3);
      }
      output.write_row(reaction_table, row);

      for (size_t k = 0; k < sources_->elements.size(); ++k) {
        const Sources::Element& e = sources_->elements[k];
        row.assign(e.width + 1, 0.0);
        row[0] = t;
        e.recorder->record_outputs(t, system.kinematics(), system.extra_state(y, e.index),
                                   std::span<double>(row).subspan(1));
        output.write_row(table_index[bodies + 2 + k], row);
      }
    }

    const double kinetic = system.kinetic_energy(y);
    const double potential = system.potential_energy(t, y);
    const double drift = system.kinematics().euler_norm_drift();
    const ConstraintViolation violation = system.constraint_violation(t, y);
    const double values[] = {t, kinetic, potential, kinetic + potential, violation.position,
                             violation.velocity, drift};
    if (written) output.write_row(energy_table, values);
    summary.max_energy_change = std::max(summary.max_energy_change,
                                         std::abs(kinetic + potential - summary.initial_energy));
    summary.max_position_violation = std::max(summary.max_position_violation, violation.position);
    summary.max_velocity_violation = std::max(summary.max_velocity_violation, violation.velocity);
    summary.max_euler_norm_drift = std::max(summary.max_euler_norm_drift, drift);
    if (progress) progress((t - model.solver.start_time) / span);
  };

  // Between report times too, so that a callback that throws on a user's interrupt stops a run
  // whose report step is long (or whose steps have become tiny) within a fraction of a second.
  auto last_progress = std::chrono::steady_clock::now();
  auto monitor = [&](double t) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_progress < kProgressInterval) return;
    last_progress = now;
    progress((t - model.solver.start_time) / span);
  };

  simulator_->start(observe, progress ? StepMonitor(monitor) : StepMonitor());
  while (!simulator_->finished()) simulator_->step();
  summary.integration = simulator_->statistics();
  output.commit();
  for (const auto& element : system.force_elements()) {
    const ForceRecorder* recorder = recorder_of(*element);
    std::string text = recorder != nullptr ? recorder->statistics_text() : std::string();
    if (!text.empty()) summary.element_statistics.push_back(std::move(text));
  }
  return summary;
}

SimulationSummary simulate(const ModelDescription& model, const std::filesystem::path& output_directory,
                           const ProgressCallback& progress) {
  SimulationRun run(model, RunOptions{.allow_large = true});
  CsvDirectory files(output_directory);
  return run.run(files, progress);
}

SimulationSummary simulate(const ModelDescription& model, SimulationOutput& output,
                           const ProgressCallback& progress) {
  SimulationRun run(model, RunOptions{.allow_large = true});
  return run.run(output, progress);
}

}  // namespace clearjoint::dynamics
