// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The lubrication module's one way to refuse an input: InvalidInput whose field_path() is the
// caller's path to the field ("joint.lubrication.viscosity", "bearing.radius") and whose message
// names the value ("bearing.radius = -1: must be positive and finite"), as the kernel's checks do.

#include <sstream>
#include <string>
#include <string_view>

#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::lubrication::detail {

/// Throws InvalidInput "<path> = <value>: <rule>", the value with 17 significant digits.
[[noreturn]] inline void refuse(std::string_view path, double value, std::string_view rule) {
  std::ostringstream detail;
  detail.precision(17);
  detail << " = " << value << ": " << rule;
  throw geometry::InvalidInput(path, detail.str());
}

/// refuse() unless `holds`.
inline void require(bool holds, std::string_view path, double value, std::string_view rule) {
  if (!holds) refuse(path, value, rule);
}

}  // namespace clearjoint::lubrication::detail
