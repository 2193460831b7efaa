// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/nonsmooth/moreau_jean_run.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/reaction_forces.hpp"
#include "clearjoint/nonsmooth/moreau_jean.hpp"

namespace clearjoint::nonsmooth {

namespace {

/// Wall-clock time between two progress calls made between report times, as
/// dynamics::SimulationRun makes them.
constexpr std::chrono::milliseconds kProgressInterval{100};
/// A span that is a whole number of steps up to rounding (1e-9 of a step) takes that number of
/// steps, not one more.
constexpr double kStepCountSlack = 1e-9;

std::vector<std::string> body_header() {
  return {"time", "x", "y", "z", "e0", "e1", "e2", "e3", "vx", "vy", "vz", "wx", "wy", "wz",
          "ax", "ay", "az", "alphax", "alphay", "alphaz"};
}

/// Throws dynamics::ModelError when two tables' names match without case (as SimulationRun).
void check_unique(const std::vector<dynamics::TablePlan>& tables) {
  std::vector<std::string> folded;
  for (const dynamics::TablePlan& t : tables) {
    std::string f = t.name;
    for (char& c : f) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (std::find(folded.begin(), folded.end(), f) != folded.end()) {
      throw dynamics::ModelError("output file " + t.name + ".csv: another table has its name (names are compared "
                                 "after characters other than letters, digits, - and _ become _, and without "
                                 "case); rename one of them");
    }
    folded.push_back(std::move(f));
  }
}

/// A force element's table: the element, its columns after time, its place in the plan, and for
/// a clearance joint its index in MoreauJean::clearance_joint_names and where its columns are.
struct ElementTable {
  size_t element = 0;
  const dynamics::ForceRecorder* recorder = nullptr;
  size_t width = 0;
  size_t table = 0;
  int site = -1;
  size_t force_column = 0;                   ///< of fx (then fy .. mz)
  size_t contact_count_column = 0;
  std::vector<size_t> slot_column;           ///< of "<slot>.depth", per ContactSlot
  size_t percussion_column = 0;              ///< of the first extra column
};

}  // namespace

struct MoreauJeanRun::Impl {
  dynamics::ModelDescription model;
  MoreauJean scheme;
  std::vector<dynamics::TablePlan> tables;
  std::vector<dynamics::BodyIndex> bodies;
  std::vector<ElementTable> elements;
  dynamics::RunSize size;
  bool ran = false;

  Impl(const dynamics::ModelDescription& m, const dynamics::RunOptions& options) : model(m), scheme(m) {
    dynamics::MultibodySystem& system = scheme.system();
    for (size_t k = 0; k < model.output_bodies.size(); ++k) {
      bodies.push_back(system.body_index(model.output_bodies[k], "output.bodies[" + std::to_string(k) + "]"));
      tables.push_back({dynamics::table_name("body_", model.output_bodies[k]), body_header()});
    }
    tables.push_back({"energy", {"time", "kinetic", "potential", "total", "position_violation",
                                 "velocity_violation", "euler_norm_drift"}});
    std::vector<std::string> reactions{"time"};
    for (const dynamics::JointEquations& joint : system.constraints().joints()) {
      for (const char* c : {"fx", "fy", "fz", "mx", "my", "mz"}) reactions.push_back(joint.name() + "." + c);
    }
    tables.push_back({"reactions", std::move(reactions)});
    const auto names = scheme.clearance_joint_names();
    for (size_t e = 0; e < system.force_elements().size(); ++e) {
      const dynamics::ForceElement& element = *system.force_elements()[e];
      const dynamics::ForceRecorder* recorder = dynamics::recorded_by_run(element, model);
      if (recorder == nullptr) continue;
      std::vector<std::string> header = recorder->output_columns();
      ElementTable t;
      t.element = e;
      t.recorder = recorder;
      t.width = header.size();
      t.table = tables.size();
      if (dynamic_cast<const dynamics::ClearanceRevoluteJoint*>(&element) != nullptr) {
        t.site = static_cast<int>(std::find(names.begin(), names.end(), element.name()) - names.begin());
        auto column = [&header](const std::string& name) {
          return static_cast<size_t>(std::find(header.begin(), header.end(), name) - header.begin());
        };
        t.force_column = column("fx");
        t.contact_count_column = column("contact_count");
        t.percussion_column = header.size();
        for (dynamics::ContactSlot slot : {dynamics::ContactSlot::radial_a, dynamics::ContactSlot::radial_b,
                                           dynamics::ContactSlot::line, dynamics::ContactSlot::axial_a,
                                           dynamics::ContactSlot::axial_b}) {
          const std::string key(dynamics::to_string(slot));
          t.slot_column.push_back(column(key + ".depth"));
          for (const char* q : kPercussionColumns) header.push_back(key + "." + q);
        }
        t.width = header.size();
      }
      header.insert(header.begin(), "time");
      elements.push_back(std::move(t));
      tables.push_back({dynamics::table_name("force_", element.name()), std::move(header)});
    }
    check_unique(tables);
    size = dynamics::run_size(model.solver, model.output_decimation, tables);
    if (!options.allow_large) dynamics::check_run_size(size);
  }

  /// The clearance joint's columns of one row: the compliant joint's record (scenario, pose,
  /// rims) with the forces replaced by the step's mean contact forces, and the percussions.
  void fill_contacts(const ElementTable& t, double h, std::span<double> values) {
    std::fill(values.begin() + static_cast<long>(t.percussion_column), values.end(), 0.0);
    // The compliant record's forces are those of a penetration law the rigid contact does not
    // have: they are replaced by the step's, slot by slot.
    for (int i = 0; i < 6; ++i) values[t.force_column + i] = 0.0;
    const double missing = std::numeric_limits<double>::quiet_NaN();
    for (size_t s = 0; s < t.slot_column.size(); ++s) {
      const size_t c = t.slot_column[s];
      values[c] = values[c + 1] = values[c + 2] = missing;
      values[c + 3] = values[c + 4] = 0.0;
      for (size_t q = 0; q < std::size(kPercussionColumns); ++q) values[t.percussion_column + 3 * s + q] = q == 2 ? missing : 0.0;
    }
    int count = 0;
    for (const ContactPercussion& p : scheme.contacts()) {
      if (p.joint != t.site) continue;
      ++count;
      geometry::Contact contact;
      contact.type = p.type;
      contact.base = p.base;
      const size_t s = static_cast<size_t>(dynamics::slot_of(contact));
      const size_t c = t.slot_column[s];
      const double friction = (p.percussion_on_journal_W - p.normal_percussion * p.normal_W).norm();
      values[c] = -p.gap;                          // depth, < 0 while the gap is open
      values[c + 1] = -p.normal_velocity_before;   // approach speed, > 0 closing
      values[c + 2] = -p.normal_velocity_before;   // the impact speed of the step
      values[c + 3] = p.normal_percussion / h;
      values[c + 4] = friction / h;
      values[t.percussion_column + 3 * s] = p.normal_percussion;
      values[t.percussion_column + 3 * s + 1] = friction;
      values[t.percussion_column + 3 * s + 2] = p.normal_velocity_after;
      for (int i = 0; i < 3; ++i) {
        values[t.force_column + i] += p.percussion_on_journal_W[i] / h;
        values[t.force_column + 3 + i] += p.moment_on_journal_W[i] / h;
      }
    }
    values[t.contact_count_column] = count;
  }

  dynamics::SimulationSummary run(dynamics::SimulationOutput& output, const dynamics::ProgressCallback& progress) {
    if (ran) throw std::logic_error("MoreauJeanRun::run: a run is made once");
    ran = true;
    dynamics::MultibodySystem& system = scheme.system();
    const dynamics::StateLayout& layout = system.layout();
    std::vector<size_t> table_index;
    for (const dynamics::TablePlan& t : tables) table_index.push_back(output.add_table(t.name, t.header));
    const size_t energy_table = table_index[bodies.size()];
    const size_t reaction_table = table_index[bodies.size() + 1];

    const double h = scheme.step_size();
    const double start = model.solver.start_time;
    const double span = model.solver.end_time - start;
    const long steps = std::max(1L, static_cast<long>(std::ceil(span / h - kStepCountSlack)));
    const long steps_per_report = std::max(1L, std::lround(model.solver.report_step / h));
    const long decimation = model.output_decimation;
    const int n = layout.velocity_size();

    dynamics::SimulationSummary summary;
    std::vector<double> previous(scheme.state().begin(), scheme.state().end());
    std::vector<double> row;
    long report_index = 0;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Eigen::VectorXd no_multipliers;

    auto observe = [&](long k) {
      const double t = scheme.time();
      const std::span<const double> y = scheme.state();
      const bool last = k == steps;
      const bool written = report_index % decimation == 0 || last;
      ++report_index;
      const double kinetic = scheme.kinetic_energy();
      const double potential = scheme.potential_energy();
      const dynamics::ConstraintViolation violation = system.constraint_violation(t, y);  // updates kinematics
      const double drift = system.kinematics().euler_norm_drift();
      if (k == 0) summary.initial_energy = kinetic + potential;
      if (written) {
        // Mean accelerations over the step ending at t; none at the start.
        Eigen::VectorXd a = Eigen::VectorXd::Constant(n, nan);
        if (k > 0) {
          for (int i = 0; i < n; ++i) {
            a[i] = (y[layout.velocity_offset(0) + i] - previous[layout.velocity_offset(0) + i]) / h;
          }
        }
        for (size_t b = 0; b < bodies.size(); ++b) {
          const dynamics::BodyState s = system.body_state(y, bodies[b]);
          const dynamics::BodyKinematics& kin = system.kinematics().body(bodies[b]);
          const dynamics::Vector3 alpha_W = kin.rotation * a.segment<3>(6 * bodies[b] + 3);
          row.assign({t});
          row.insert(row.end(), s.position_W.data(), s.position_W.data() + 3);
          row.insert(row.end(), s.euler_parameters.data(), s.euler_parameters.data() + 4);
          row.insert(row.end(), s.velocity_W.data(), s.velocity_W.data() + 3);
          row.insert(row.end(), kin.angular_velocity_W.data(), kin.angular_velocity_W.data() + 3);
          row.insert(row.end(), a.data() + 6 * bodies[b], a.data() + 6 * bodies[b] + 3);
          row.insert(row.end(), alpha_W.data(), alpha_W.data() + 3);
          output.write_row(table_index[b], row);
        }
        // Reactions: eq. (37) with lambda = -mu / h, the mean over the step.
        row.assign({t});
        const auto mu = scheme.bilateral_percussions();
        const Eigen::VectorXd lambda =
            k > 0 && !mu.empty() ? Eigen::VectorXd(-Eigen::Map<const Eigen::VectorXd>(mu.data(), static_cast<long>(mu.size())) / h)
                                 : Eigen::VectorXd();
        for (size_t j = 0; j < system.constraints().joints().size(); ++j) {
          if (lambda.size() == 0) {
            row.insert(row.end(), 6, k > 0 ? 0.0 : nan);
            continue;
          }
          const dynamics::JointReaction r = dynamics::joint_reaction(system, static_cast<int>(j), lambda);
          row.insert(row.end(), r.force_W.data(), r.force_W.data() + 3);
          row.insert(row.end(), r.moment_W.data(), r.moment_W.data() + 3);
        }
        output.write_row(reaction_table, row);
        for (const ElementTable& e : elements) {
          row.assign(e.width + 1, 0.0);
          row[0] = t;
          const std::span<double> values = std::span<double>(row).subspan(1);
          e.recorder->record_outputs(t, system.kinematics(), system.extra_state(y, e.element),
                                     values.first(e.site >= 0 ? e.percussion_column : e.width));
          if (e.site >= 0) fill_contacts(e, h, values);
          output.write_row(table_index[e.table], row);
        }
        const double energy[] = {t, kinetic, potential, kinetic + potential, violation.position, violation.velocity, drift};
        output.write_row(energy_table, energy);
      }
      summary.max_energy_change = std::max(summary.max_energy_change, std::abs(kinetic + potential - summary.initial_energy));
      summary.max_position_violation = std::max(summary.max_position_violation, violation.position);
      summary.max_velocity_violation = std::max(summary.max_velocity_violation, violation.velocity);
      summary.max_euler_norm_drift = std::max(summary.max_euler_norm_drift, drift);
      if (progress) progress(std::min(1.0, (t - start) / span));
    };

    observe(0);
    auto last_progress = std::chrono::steady_clock::now();
    for (long k = 1; k <= steps; ++k) {
      previous.assign(scheme.state().begin(), scheme.state().end());
      scheme.step();
      if (k % steps_per_report == 0 || k == steps) {
        observe(k);
      } else if (progress) {
        const auto now = std::chrono::steady_clock::now();
        if (now - last_progress >= kProgressInterval) {
          last_progress = now;
          progress((scheme.time() - start) / span);
        }
      }
    }
    output.commit();

    const MoreauJeanStatistics& s = scheme.statistics();
    summary.integration.steps = s.steps;
    summary.integration.smallest_step = summary.integration.largest_step = h;
    std::string line = "moreau_jean: " + std::to_string(s.steps) + " steps of " + dynamics::format_shortest(h) +
                       " s, " + std::to_string(s.contact_problems) + " contact problems, " +
                       std::to_string(s.solver_iterations) + " fc3d NSGS sweeps, largest residual " +
                       dynamics::format_shortest(s.largest_solver_error) + ", " + std::to_string(s.unconverged_steps) +
                       " unconverged steps";
    if (s.unconverged_steps > 0) line += " (the first at t = " + dynamics::format_shortest(s.first_unconverged_time) + " s)";
    if (s.fallback_solves > 0) {
      line += ", " + std::to_string(s.fallback_solves) + " problems missed by NSGS solved again by fc3d PROX (" +
              std::to_string(s.fallback_iterations) + " iterations)";
    }
    summary.element_statistics.push_back(std::move(line));
    if (s.fclib_problems_written > 0) {
      summary.element_statistics.push_back("moreau_jean: " + std::to_string(s.fclib_problems_written) +
                                           " contact problems written as FCLIB files (--write-fclib)");
    }
    return summary;
  }
};

MoreauJeanRun::MoreauJeanRun(const dynamics::ModelDescription& model, const dynamics::RunOptions& options)
    : impl_(std::make_unique<Impl>(model, options)) {}
MoreauJeanRun::~MoreauJeanRun() = default;
const std::vector<dynamics::TablePlan>& MoreauJeanRun::tables() const { return impl_->tables; }
const dynamics::ModelDescription& MoreauJeanRun::model() const { return impl_->model; }
void MoreauJeanRun::write_fclib(const FclibExport& fclib) { impl_->scheme.write_fclib(fclib); }
dynamics::SimulationSummary MoreauJeanRun::run(dynamics::SimulationOutput& output,
                                               const dynamics::ProgressCallback& progress) {
  return impl_->run(output, progress);
}

}  // namespace clearjoint::nonsmooth
