// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The accuracy evaluation: every method on every input of the chosen families, scored against
/// the multiprecision reference of the joint as given, which is what the certificates are about
/// (and, for the certified pipeline, also of the joint with exactly normalised axes, a diagnostic).

#include <string>
#include <vector>

#include "input_families.hpp"
#include "json_output.hpp"

namespace clearjoint::bench {

struct AccuracyOptions {
  SuiteSize size = SuiteSize::full;
  std::vector<std::string> families;  ///< empty: all
  int threads = 2;
  /// Failures listed per method and family for the uncertified methods (all are counted); every
  /// failure of the certified pipeline is listed.
  int listed_failures = 10;
  bool progress = true;  ///< progress lines on stderr
};

struct AccuracyResult {
  Json report;  ///< the whole report (docs/reports/benchmarks.md is generated from it)
  /// Certified-pipeline failures against the joint as given (its certificates' claim), and
  /// against the joint with exactly normalised axes (a diagnostic), over all families.
  std::size_t certified_failures_as_given = 0;
  std::size_t certified_failures_exact_axes = 0;
  std::size_t reference_undecided = 0;
};

AccuracyResult run_accuracy(const AccuracyOptions& options);

}  // namespace clearjoint::bench
