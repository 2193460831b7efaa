// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/model/detection_options.hpp"

#include <numbers>

#include "model/input_checks.hpp"

namespace clearjoint::geometry {

void validate(const DetectionOptions& options, std::string_view name) {
  // Below pi/2: at pi/2 every pair of axes would be "parallel" (NaN fails the comparison).
  const double tolerance = options.parallel_angle_tolerance;
  if (!(tolerance >= 0.0 && tolerance < 0.5 * std::numbers::pi)) {
    detail::reject(name, "parallel_angle_tolerance", detail::format(tolerance), "must lie in [0, pi/2) radians");
  }
}

}  // namespace clearjoint::geometry
