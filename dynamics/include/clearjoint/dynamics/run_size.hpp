// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// How big a run will be, known before it starts, and the guard that refuses runs far beyond any
/// real study unless asked for: a slip of the exponent (end_time 1e9, report_step 1e-21) must not
/// fill the disk or run for days. docs/command-line.md ("Limits") states the numbers.

#include <span>

#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/simulation_output.hpp"

namespace clearjoint::dynamics {

/// Longest simulated span, end_time - start_time [s]. The paper's runs last 1 s; a slider-crank
/// turns hundreds of times in 1000 s.
inline constexpr double kMaxSimulatedSpan = 1000.0;
/// Most report rows (report times) of a run: 100 s at the paper's report step of 1e-5 s.
inline constexpr double kMaxReportRows = 1e7;
/// Largest estimated total size of the CSV files [bytes].
inline constexpr double kMaxOutputBytes = 4e9;

struct RunSize {
  double span = 0.0;         ///< end_time - start_time [s]
  double report_rows = 0.0;  ///< rows of every CSV file, header aside
  double columns = 0.0;      ///< numbers written per report time, over all files
  double output_bytes = 0.0; ///< estimate: rows x columns x kBytesPerNumber (CSV)
};

/// The size of a run with these solver settings that writes `tables` at every
/// `decimation`-th report time (and the last). Throws ModelError for unusable settings.
RunSize run_size(const IntegratorSettings& solver, long decimation, std::span<const TablePlan> tables);

/// Throws ModelError naming the setting and the limit if `size` exceeds any limit above; the
/// message says how to lift the guard (`--allow-large` on the command line).
void check_run_size(const RunSize& size);

}  // namespace clearjoint::dynamics
