// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/model/rim_arc.hpp"

#include <numbers>

#include "arithmetic/angles.hpp"

namespace clearjoint::geometry {

double RimArc::sweep() const noexcept {
  if (full) return 2 * std::numbers::pi;
  return detail::wrap_angle(end - begin);
}

double RimArc::middle() const noexcept {
  if (full) return detail::wrap_angle(begin + std::numbers::pi);
  return detail::wrap_angle(begin + 0.5 * sweep());
}

}  // namespace clearjoint::geometry
