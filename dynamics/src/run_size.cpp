// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/run_size.hpp"

#include <cmath>
#include <string>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/model_builder.hpp"

namespace clearjoint::dynamics {

namespace {

/// Bytes a number takes in the CSV files: the shortest round-trip form of a double is at most
/// 24 characters ("-2.2250738585072014e-308"); typical values take ~20, plus the comma.
constexpr double kBytesPerNumber = 21.0;

constexpr int kBodyColumns = 20;    // body_<name>.csv
constexpr int kEnergyColumns = 7;   // energy.csv
constexpr int kReactionColumns = 6; // per joint in reactions.csv

std::string lift_hint() {
  return " (a guard against a slip of the exponent; pass --allow-large, or allow_large=True in "
         "Python, to run it anyway)";
}

}  // namespace

RunSize estimate_run_size(const ModelDescription& model) {
  validate(model.solver);
  RunSize size;
  size.span = model.solver.end_time - model.solver.start_time;
  size.report_rows = std::ceil(size.span / model.solver.report_step) + 1.0;
  const BuiltModel built = build_model(model);
  double columns = kEnergyColumns + 1.0 + kReactionColumns * static_cast<double>(model.joints.size()) + 1.0;
  columns += (kBodyColumns + 0.0) * static_cast<double>(model.output_bodies.size());
  for (const auto& element : built.system->force_elements()) {
    const double width = static_cast<double>(element->output_columns().size());
    if (width > 0.0) columns += width + 1.0;  // an upper bound: every element that records any
  }
  size.columns = columns;
  size.output_bytes = size.report_rows * columns * kBytesPerNumber;
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
