// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The option list of the joint's detection: every member of DetectionOptions (its
/// IntersectionOptions flattened) with the key each front-end spells it by: the command line's
/// "options" object, a model file's "detection" object, Python's keyword arguments and the C
/// struct's members. The command line and the model file read their options through it; Python
/// and C are checked against it by tests that change one option at a time
/// (support/testing/option_changes.hpp). The compiler checks the list itself: a member added to
/// either struct without its line here does not build.

#include <string_view>
#include <vector>

#include "clearjoint/geometry/model/detection_options.hpp"
#include "clearjoint/geometry/model/field_lists.hpp"  // detail::aggregate_member_count

namespace clearjoint::geometry {

/// Calls visitor(key, member) for each option, in this order: "certify" (bool),
/// "exact_fallback" (bool), "parallel_angle_tolerance" (double, radians). `Options` is
/// DetectionOptions or const DetectionOptions.
template <class Options, class Visitor>
constexpr void visit_options(Options& options, Visitor&& visitor) {
  visitor(std::string_view("certify"), options.intersection.certify);
  visitor(std::string_view("exact_fallback"), options.intersection.exact_fallback);
  visitor(std::string_view("parallel_angle_tolerance"), options.parallel_angle_tolerance);
}

/// How many options visit_options lists.
inline constexpr int kDetectionOptionCount = 3;

// DetectionOptions holds `intersection` and one more member; each of IntersectionOptions' members
// is one option. A member added to either struct needs its line in visit_options.
static_assert(detail::aggregate_member_count<IntersectionOptions>() +
                      detail::aggregate_member_count<DetectionOptions>() - 1 ==
                  kDetectionOptionCount,
              "a member of DetectionOptions or IntersectionOptions is missing from visit_options");

/// Every option's value in list order, flags as 0 or 1: two option sets compare equal exactly
/// when these do.
inline std::vector<double> option_values(const DetectionOptions& options) {
  std::vector<double> values;
  visit_options(options, [&values](std::string_view, const auto& value) { values.push_back(static_cast<double>(value)); });
  return values;
}

}  // namespace clearjoint::geometry
