// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Choices by name, for the front ends (model files, Python, the command line): every name
/// comes from the library's own to_string tables (kCavitationModels, kBearingMotions,
/// kBearingMethods), so that a front end cannot drift from them.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace clearjoint::lubrication {

/// The value of `values` whose to_string is `name`, or nullopt.
template <typename Value, std::size_t N>
std::optional<Value> value_named(std::string_view name, const std::array<Value, N>& values) {
  for (const Value value : values) {
    if (to_string(value) == name) return value;
  }
  return std::nullopt;
}

/// "a, b, c": every value's name, in the table's order, for messages.
template <typename Value, std::size_t N>
std::string known_names(const std::array<Value, N>& values) {
  std::string names;
  for (const Value value : values) {
    if (!names.empty()) names += ", ";
    names += to_string(value);
  }
  return names;
}

}  // namespace clearjoint::lubrication
