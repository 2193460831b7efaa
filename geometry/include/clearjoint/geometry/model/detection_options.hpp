// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The options of the joint's contact detection (detect_contacts.hpp), apart from the detection,
/// so that a parameter struct can hold them without depending on the kernel's queries.

#include <string_view>

#include "clearjoint/geometry/model/intersection_options.hpp"

namespace clearjoint::geometry {

struct DetectionOptions {
  /// Passed to the kernel queries.
  IntersectionOptions intersection{};
  /// Axes whose angle (or angle to the opposite direction) is at most this many radians are
  /// treated as parallel (eqs. 6-10 instead of eqs. 11-21). 0 (default): parallel only when
  /// a_i x a_j = 0 exactly (eq. 5). A positive tolerance is evaluated in double precision, and
  /// contacts found under it are `uncertain` ("axes treated as parallel within the tolerance").
  double parallel_angle_tolerance = 0.0;
};

/// The one check of the options, for every front-end: throw InvalidInput naming the field and
/// its value ("options.parallel_angle_tolerance = 2: must lie in [0, pi/2) radians"). `name` is
/// the caller's path to the options ("forces[0].detection").
void validate(const DetectionOptions& options, std::string_view name = "options");

}  // namespace clearjoint::geometry
