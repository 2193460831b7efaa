// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/run_size.hpp"

#include <cmath>
#include <string>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

namespace {

/// Bytes a number takes in the CSV files: the shortest round-trip form of a double is at most
/// 24 characters ("-2.2250738585072014e-308"); typical values take ~20, plus the comma.
constexpr double kBytesPerNumber = 21.0;

std::string lift_hint() {
  return " (a guard against a slip of the exponent; pass --allow-large, or allow_large=True in "
         "Python, to run it anyway)";
}

}  // namespace

RunSize run_size(const IntegratorSettings& solver, long decimation, std::span<const TablePlan> tables) {
  validate(solver);
  RunSize size;
  size.span = solver.end_time - solver.start_time;
  const double reports = std::ceil(size.span / solver.report_step);
  size.report_rows = std::ceil(reports / static_cast<double>(decimation)) + 1.0;
  for (const TablePlan& table : tables) size.columns += static_cast<double>(table.header.size());
  size.output_bytes = size.report_rows * size.columns * kBytesPerNumber;
  return size;
}

void check_run_size(const RunSize& size) {
  if (size.span > kMaxSimulatedSpan) {
    throw ModelError("solver.end_time - solver.start_time = " + format_number(size.span) +
                     " s: longer than " + format_number(kMaxSimulatedSpan) + " s" + lift_hint());
  }
  if (size.report_rows > kMaxReportRows) {
    throw ModelError("solver.report_step: " + format_number(size.report_rows) +
                     " report times, more than " + format_number(kMaxReportRows) + lift_hint());
  }
  if (size.output_bytes > kMaxOutputBytes) {
    throw ModelError("output: about " + format_number(std::round(size.output_bytes / 1e6)) +
                     " MB of CSV files, more than " + format_number(kMaxOutputBytes / 1e6) +
                     " MB" + lift_hint());
  }
}

}  // namespace clearjoint::dynamics
