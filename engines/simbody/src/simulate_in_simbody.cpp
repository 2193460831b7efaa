// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/simbody/simulate_in_simbody.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "clearjoint/simbody/model_in_simbody.hpp"
#include "clearjoint/dynamics/csv_directory.hpp"
#include "clearjoint/dynamics/simulation.hpp"
#include "clearjoint/dynamics/stall_guard.hpp"

namespace clearjoint::simbody {

namespace {

/// As dynamics::integrate(): a rounding excess of span / report_step adds no report time a few
/// ulps before end_time.
constexpr double kReportCountSlack = 1e-9;
/// Most steps Simbody takes inside one stepTo before it hands control back, so that the step
/// budget (solver.max_steps), the stall rule (dynamics::StallGuard) and the progress callback are
/// looked at at least this often, also when the steps collapse between two report times. Some
/// 1,000 steps are milliseconds of a run.
constexpr int kStepsBetweenChecks = 1'000;
/// Wall-clock time between two progress calls made between report times, as clearjoint's own
/// run makes them (dynamics::SimulationRun).
constexpr std::chrono::milliseconds kProgressInterval{100};

std::vector<std::string> body_header() {
  return {"time", "x", "y", "z", "e0", "e1", "e2", "e3", "vx", "vy", "vz", "wx", "wy", "wz",
          "ax", "ay", "az", "alphax", "alphay", "alphaz"};
}

/// A body table: its body, its place in the plan, and the Euler parameters of the last report
/// time (for their sign).
struct BodyTable {
  SimTK::MobilizedBody body;
  std::size_t table = 0;
  SimTK::Vec4 last_euler_parameters;
};

/// A clearance joint's table: the joint, its number of columns after time, its place in the plan.
struct ForceTable {
  const ClearanceRevoluteForce* joint = nullptr;
  std::size_t width = 0;
  std::size_t table = 0;
};

void append(std::vector<double>& row, const SimTK::Vec3& v) { row.insert(row.end(), {v[0], v[1], v[2]}); }

/// Largest ||q| - 1| over the quaternions of Ball and Free mobilizers (their first four q).
double quaternion_norm_drift(const SimTK::SimbodyMatterSubsystem& matter, const SimTK::State& state) {
  double drift = 0.0;
  for (SimTK::MobilizedBodyIndex b(1); b < matter.getNumBodies(); ++b) {
    const SimTK::MobilizedBody& body = matter.getMobilizedBody(b);
    if (body.getNumQ(state) == body.getNumU(state)) continue;  // no quaternion
    SimTK::Vec4 q;
    for (int k = 0; k < 4; ++k) q[k] = body.getOneQ(state, SimTK::MobilizerQIndex(k));
    drift = std::max(drift, std::abs(q.norm() - 1.0));
  }
  return drift;
}

double largest_magnitude(const SimTK::Vector& v) {
  double largest = 0.0;
  for (int k = 0; k < v.size(); ++k) largest = std::max(largest, std::abs(v[k]));
  return largest;
}

/// The tables of the Simbody route, in the order dynamics::SimulationRun plans clearjoint's own
/// (bodies, energy, reactions, force elements), with the table each writes.
struct SimbodyTables {
  std::vector<dynamics::TablePlan> plan;
  std::vector<BodyTable> bodies;
  std::vector<ForceTable> forces;
};

SimbodyTables simbody_tables(const dynamics::ModelDescription& model, const SimbodyModel& built) {
  SimbodyTables t;
  for (std::size_t k = 0; k < model.output_bodies.size(); ++k) {
    const std::string& name = model.output_bodies[k];
    const SimTK::MobilizedBody& body = built.body(name, "output.bodies[" + std::to_string(k) + "]");
    const dynamics::Vector4 p0 = [&] {
      for (const auto& b : model.bodies) {
        if (b.properties.name == name) return b.initial.euler_parameters;
      }
      return dynamics::Vector4(1.0, 0.0, 0.0, 0.0);
    }();
    t.bodies.push_back({body, t.plan.size(), SimTK::Vec4(p0[0], p0[1], p0[2], p0[3])});
    t.plan.push_back({dynamics::table_name("body_", name), body_header()});
  }
  t.plan.push_back({"energy", {"time", "kinetic", "potential", "total", "position_violation",
                               "velocity_violation", "euler_norm_drift"}});
  std::vector<std::string> reaction_header{"time"};
  for (const JointInSimbody& joint : built.joints()) {
    for (const char* c : {"fx", "fy", "fz", "mx", "my", "mz"}) reaction_header.push_back(joint.name + "." + c);
  }
  t.plan.push_back({"reactions", std::move(reaction_header)});
  for (const auto& joint : built.clearance_joints()) {
    const std::string name(joint->joint().name());
    const auto& wanted = model.output_force_elements;
    if (!model.output_all_force_elements && std::find(wanted.begin(), wanted.end(), name) == wanted.end()) {
      continue;
    }
    std::vector<std::string> header = joint->joint().output_columns();
    const std::size_t width = header.size();
    header.insert(header.begin(), "time");
    t.forces.push_back({joint.get(), width, t.plan.size()});
    t.plan.push_back({dynamics::table_name("force_", name), std::move(header)});
  }
  return t;
}

/// Throws std::logic_error naming the first table whose name or columns differ between the two
/// plans: a column added to one engine's tables and not to the other's.
void check_same_plan(const std::vector<dynamics::TablePlan>& simbody,
                     const std::vector<dynamics::TablePlan>& clearjoint) {
  for (std::size_t k = 0; k < std::max(simbody.size(), clearjoint.size()); ++k) {
    const bool same = k < simbody.size() && k < clearjoint.size() && simbody[k].name == clearjoint[k].name &&
                      simbody[k].header == clearjoint[k].header;
    if (same) continue;
    const std::string name = k < clearjoint.size() ? clearjoint[k].name : simbody[k].name;
    throw std::logic_error("the Simbody route's table " + std::to_string(k) + " (" + name +
                           ") differs from clearjoint's plan in its name or columns");
  }
}

}  // namespace

dynamics::SimulationSummary simulate_in_simbody(const dynamics::SimulationRun& run,
                                                dynamics::SimulationOutput& output,
                                                const dynamics::ProgressCallback& progress) {
  const dynamics::ModelDescription& model = run.model();
  SimbodyModel built(model);
  SimTK::MultibodySystem& system = built.system();
  const SimTK::SimbodyMatterSubsystem& matter = built.matter();

  SimbodyTables tables = simbody_tables(model, built);
  check_same_plan(tables.plan, run.tables());
  std::vector<std::size_t> table_index;
  for (const dynamics::TablePlan& table : tables.plan) table_index.push_back(output.add_table(table.name, table.header));
  std::vector<BodyTable>& bodies = tables.bodies;
  const std::vector<ForceTable>& forces = tables.forces;
  const std::size_t energy_table = table_index[bodies.size()];
  const std::size_t reaction_table = table_index[bodies.size() + 1];

  dynamics::SimulationSummary summary;
  summary.initial_conditions = built.initial_conditions();
  summary.initial_energy = system.calcEnergy(built.initial_state());
  const double span = model.solver.end_time - model.solver.start_time;
  std::vector<double> row;
  SimTK::Vector_<SimTK::SpatialVec> mobilizer_reactions;
  const long decimation = model.output_decimation;
  long report_index = 0;

  auto write_reactions_and_forces = [&](const SimTK::State& state, double t) {
    matter.calcMobilizerReactionForces(state, mobilizer_reactions);
    row.assign({t});
    for (const JointInSimbody& joint : built.joints()) {
      SimTK::Vec3 force, moment;
      const SimTK::Vec3 p_GQ = joint.reported_body.findStationLocationInGround(state, joint.point_on_reported_body);
      if (joint.closes_loop) {
        force = joint.reported_body_is_child ? joint.loop.getBallReactionForceOnBody2(state)
                                             : joint.loop.getBallReactionForceOnBody1(state);
        moment = SimTK::Vec3(0.0);  // applied at the joint point itself
      } else {
        // The mobilizer's wrench on its child at M's origin; the parent gets the opposite.
        const SimTK::SpatialVec& on_child = mobilizer_reactions[joint.mobilizer.getMobilizedBodyIndex()];
        const SimTK::Vec3 p_GMo = joint.mobilizer.findStationLocationInGround(
            state, joint.mobilizer.getOutboardFrame(state).p());
        const double sign = joint.reported_body_is_child ? 1.0 : -1.0;
        force = sign * on_child[1];
        moment = sign * (on_child[0] + (p_GMo - p_GQ) % on_child[1]);
      }
      append(row, force);
      append(row, moment);
    }
    output.write_row(reaction_table, row);

    for (const ForceTable& f : forces) {
      row.assign(f.width + 1, 0.0);
      row[0] = t;
      f.joint->record_outputs(state, std::span<double>(row).subspan(1));
      output.write_row(table_index[f.table], row);
    }
  };

  auto observe = [&](const SimTK::State& state, bool last) {
    // Rows of every decimation-th report time and of the last, as dynamics::SimulationRun writes
    // them; the summary and the Euler parameters' sign see every one.
    const bool written = report_index % decimation == 0 || last;
    ++report_index;
    system.realize(state, SimTK::Stage::Acceleration);
    const double t = state.getTime();
    for (BodyTable& b : bodies) {
      const SimTK::Transform& X_GB = b.body.getBodyTransform(state);
      SimTK::Vec4 e = X_GB.R().convertRotationToQuaternion().asVec4();
      if (~e * b.last_euler_parameters < 0.0) e = -e;  // q and -q are one rotation
      b.last_euler_parameters = e;
      if (!written) continue;
      const SimTK::SpatialVec& V = b.body.getBodyVelocity(state);
      const SimTK::SpatialVec& A = b.body.getBodyAcceleration(state);
      row.assign({t});
      append(row, X_GB.p());
      row.insert(row.end(), {e[0], e[1], e[2], e[3]});
      append(row, V[1]);
      append(row, V[0]);
      append(row, A[1]);
      append(row, A[0]);
      output.write_row(table_index[b.table], row);
    }
    if (written) write_reactions_and_forces(state, t);

    const double kinetic = system.calcKineticEnergy(state);
    const double potential = system.calcPotentialEnergy(state);
    const double position_violation = largest_magnitude(state.getQErr());
    const double velocity_violation = largest_magnitude(state.getUErr());
    const double drift = quaternion_norm_drift(matter, state);
    if (written) {
      output.write_row(energy_table, std::vector<double>{t, kinetic, potential, kinetic + potential,
                                                         position_violation, velocity_violation, drift});
    }
    summary.max_energy_change =
        std::max(summary.max_energy_change, std::abs(kinetic + potential - summary.initial_energy));
    summary.max_position_violation = std::max(summary.max_position_violation, position_violation);
    summary.max_velocity_violation = std::max(summary.max_velocity_violation, velocity_violation);
    summary.max_euler_norm_drift = std::max(summary.max_euler_norm_drift, drift);
    if (progress) progress((t - model.solver.start_time) / span);
  };

  SimTK::RungeKuttaMersonIntegrator integrator(system);
  integrator.setAccuracy(model.solver.relative_tolerance);
  integrator.setInitialStepSize(model.solver.initial_step);
  integrator.setMinimumStepSize(model.solver.minimum_step);
  integrator.setFinalTime(model.solver.end_time);
  integrator.setInternalStepLimit(kStepsBetweenChecks);
  SimTK::TimeStepper stepper(system, integrator);
  // Hand control back at the step limit too (the TimeStepper otherwise goes on inside stepTo).
  stepper.setReportAllSignificantStates(true);
  stepper.initialize(built.initial_state());
  observe(stepper.getState(), false);

  const long report_count = std::max(
      1L, std::lround(std::ceil(span / model.solver.report_step * (1.0 - kReportCountSlack))));
  summary.integration.smallest_step = model.solver.report_step;
  dynamics::StallGuard stall(model.solver, model.solver.start_time, 0);
  auto last_progress = std::chrono::steady_clock::now();
  for (long k = 1; k <= report_count; ++k) {
    const double t = k == report_count ? model.solver.end_time
                                       : model.solver.start_time + double(k) * model.solver.report_step;
    while (stepper.getTime() < t) {
      const SimTK::Integrator::SuccessfulStepStatus status = stepper.stepTo(t);
      if (status == SimTK::Integrator::EndOfSimulation && stepper.getTime() < t) {
        throw dynamics::SolverError("Simbody stopped at t = " + dynamics::format_number(stepper.getTime()) +
                                    ": " + integrator.getTerminationReasonString(integrator.getTerminationReason()));
      }
      if (integrator.getNumStepsTaken() >= model.solver.max_steps) {
        throw dynamics::SolverError("integration stopped at t = " + dynamics::format_number(stepper.getTime()) +
                                    ": Simbody took more than solver.max_steps = " +
                                    std::to_string(model.solver.max_steps) + " steps");
      }
      const double step = integrator.getPreviousStepSizeTaken();
      summary.integration.smallest_step = std::min(summary.integration.smallest_step, step);
      summary.integration.largest_step = std::max(summary.integration.largest_step, step);
      stall.check(stepper.getTime(), integrator.getNumStepsTaken(), "Simbody");
      // Between report times too, so that a long report step or collapsed steps still show
      // progress and a callback that throws on a user's interrupt stops the run at once.
      const auto now = std::chrono::steady_clock::now();
      if (progress && stepper.getTime() < t && now - last_progress >= kProgressInterval) {
        last_progress = now;
        progress((stepper.getTime() - model.solver.start_time) / span);
      }
    }
    observe(stepper.getState(), k == report_count);
  }
  output.commit();

  summary.integration.steps = integrator.getNumStepsTaken();
  summary.integration.derivative_calls = integrator.getNumRealizations();
  for (const auto& joint : built.clearance_joints()) {
    summary.integration.located_onsets += static_cast<long>(joint->joint().recorded_impacts().size());
    std::string text = joint->joint().statistics_text();
    if (!text.empty()) summary.element_statistics.push_back(std::move(text));
  }
  return summary;
}

dynamics::SimulationSummary simulate_in_simbody(const dynamics::ModelDescription& model,
                                                dynamics::SimulationOutput& output,
                                                const dynamics::ProgressCallback& progress) {
  const dynamics::SimulationRun plan(model, dynamics::RunOptions{.allow_large = true});
  return simulate_in_simbody(plan, output, progress);
}

dynamics::SimulationSummary simulate_in_simbody(const dynamics::ModelDescription& model,
                                                const std::filesystem::path& output_directory,
                                                const dynamics::ProgressCallback& progress) {
  // The model is built twice (once here to check it before the directory exists): building is
  // cheap beside the run.
  const dynamics::SimulationRun plan(model, dynamics::RunOptions{.allow_large = true});
  { SimbodyModel check(model); }
  dynamics::CsvDirectory files(output_directory);
  return simulate_in_simbody(plan, files, progress);
}

}  // namespace clearjoint::simbody
