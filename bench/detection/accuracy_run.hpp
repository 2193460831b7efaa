#pragma once
/// \file
/// The accuracy evaluation: every method on every input of the chosen families, scored against
/// the multiprecision reference of the joint as given (and, for the certified pipeline, also of the
/// joint as the library rounds it, which is what its certificates are about).

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
  Json report;  ///< the whole report (docs/benchmarks.md is generated from it)
  /// Certified-pipeline failures against the joint as given, and against the joint as the
  /// library rounds it (its certificates' claim), over all families.
  std::size_t certified_failures_as_given = 0;
  std::size_t certified_failures_as_rounded = 0;
  std::size_t reference_undecided = 0;
};

AccuracyResult run_accuracy(const AccuracyOptions& options);

}  // namespace clearjoint::bench
