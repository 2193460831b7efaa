// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A check for the front-ends that take detection options (the command line, a model file, the
/// C API, Python): change one option at a time and require the front-end to carry it to the
/// library. An option added to visit_options (which the compiler requires) that a front-end
/// leaves out fails that front-end's test, naming the option.

#include <string_view>
#include <type_traits>

#include "clearjoint/geometry/model/option_fields.hpp"

namespace clearjoint::geometry {

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
