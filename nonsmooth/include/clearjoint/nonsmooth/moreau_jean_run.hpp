// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A whole Moreau-Jean run (docs/nonsmooth.md, "Run folder"): the tables of a compliant run
/// (dynamics/simulation.hpp: body_<name>, energy, reactions, force_<name>), with the same names
/// and columns, written to any dynamics::SimulationOutput, so that a run folder, plot, view and
/// read_run treat both formulations alike. Per step quantities are means over the step ending at
/// the row's time: accelerations (v(k+1) - v(k)) / h, reactions and contact forces impulse / h.
/// Each clearance joint's table has, after the compliant columns, three per contact slot:
/// `<slot>.normal_percussion`, `<slot>.friction_percussion` [N s] and `<slot>.rebound_speed`
/// (u_N after the step [m/s]).

#include <memory>
#include <string>
#include <vector>

#include "clearjoint/dynamics/model_description.hpp"
#include "clearjoint/dynamics/run_size.hpp"
#include "clearjoint/dynamics/simulation.hpp"
#include "clearjoint/dynamics/simulation_output.hpp"
#include "clearjoint/nonsmooth/fclib_export.hpp"

namespace clearjoint::nonsmooth {

/// The extra columns of a clearance joint's table, per contact slot, in this order.
inline constexpr const char* kPercussionColumns[] = {"normal_percussion", "friction_percussion", "rebound_speed"};

/// One Moreau-Jean run, planned before it starts, as dynamics::SimulationRun plans a compliant
/// one: the model built, the tables decided and checked (colliding names, the size guard) before
/// any output exists. Rows are written at the step nearest each report time (every
/// round(report_step / h)-th step), and at the last step, which ends at or just after end_time
/// (steps are never shortened); output.decimation applies as in a compliant run.
class MoreauJeanRun {
 public:
  /// Throws dynamics::ModelError (a bad model or settings, colliding table names, a run beyond
  /// the size guard) or dynamics::SolverError (inconsistent initial conditions).
  explicit MoreauJeanRun(const dynamics::ModelDescription& model, const dynamics::RunOptions& options = {});
  MoreauJeanRun(const MoreauJeanRun&) = delete;
  MoreauJeanRun& operator=(const MoreauJeanRun&) = delete;
  ~MoreauJeanRun();

  const std::vector<dynamics::TablePlan>& tables() const;
  const dynamics::ModelDescription& model() const;
  /// Write the run's contact problems as FCLIB files (fclib_export.hpp says which); before run().
  /// Throws dynamics::ModelError naming --write-fclib for a folder that cannot be written.
  void write_fclib(const FclibExport& fclib);

  /// Integrate and write; once. The summary's integration.steps counts the steps (smallest and
  /// largest step h), element_statistics holds a "moreau_jean: ..." line with the contact
  /// problems, solver sweeps and unconverged steps (the first one's time). Throws
  /// dynamics::SolverError (stop_on_unconverged, a refused pose) or what `output` throws;
  /// `output` is committed only after the last row.
  dynamics::SimulationSummary run(dynamics::SimulationOutput& output, const dynamics::ProgressCallback& progress = {});

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clearjoint::nonsmooth
