// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The option list of the joint's detection: every member of DetectionOptions (its
/// IntersectionOptions flattened) with the key each front-end spells it by: the command line's
/// "options" object, a model file's "detection" object, Python's keyword arguments and the C
/// struct's members. The command line and the model file read their options through it; Python
/// and C are checked against it by tests that change one option at a time. The compiler checks
/// the list itself: a member added to either struct without its line here does not build.

#include <string_view>
#include <type_traits>
#include <vector>

#include "clearjoint/geometry/detection_options.hpp"
#include "clearjoint/geometry/result_fields.hpp"  // detail::aggregate_member_count

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

/// The defaults with option number `target` (in list order) changed to a value a front-end must
/// pass on: a flag flipped, a number 0.125 (a valid parallel_angle_tolerance, radians). For the
/// tests of the front-ends, which must carry each option to the library.
struct OptionChange {
  std::string_view key;
  DetectionOptions options;
};
inline OptionChange change_one_option(int target) {
  OptionChange change{};
  int index = 0;
  visit_options(change.options, [&](std::string_view key, auto& value) {
    if (index++ != target) return;
    change.key = key;
    if constexpr (std::is_same_v<std::remove_reference_t<decltype(value)>, bool>) {
      value = !value;
    } else {
      value = value == 0.125 ? 0.25 : 0.125;
    }
  });
  return change;
}

}  // namespace clearjoint::geometry
