// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The field list of the lubrication library's public results, in the form of
/// clearjoint/geometry/joint/result_fields.hpp: one list per type, with the keys every front-end spells
/// them by. `clearjoint bearing` and Python's `bearing_characteristics` write the result through
/// geometry::visit_fields, and the static_assert below fails the build when a member of
/// BearingCharacteristics has no line here.

#include <tuple>

#include "clearjoint/geometry/joint/result_fields.hpp"
#include "clearjoint/lubrication/bearing_characteristics.hpp"

namespace clearjoint::geometry {

template <>
struct ResultFields<lubrication::BearingCharacteristics> {
  using B = lubrication::BearingCharacteristics;
  static constexpr std::tuple fields{fields::plain("sommerfeld_number", &B::sommerfeld_number),
                                     fields::plain("attitude_angle", &B::attitude_angle),
                                     fields::plain("side_flow_variable", &B::side_flow_variable),
                                     fields::plain("max_pressure_ratio", &B::max_pressure_ratio),
                                     fields::plain("iterations", &B::iterations),
                                     fields::plain("converged", &B::converged)};
};

static_assert(detail::lists_every_member<lubrication::BearingCharacteristics>(),
              "a member of BearingCharacteristics is missing from its field list");

}  // namespace clearjoint::geometry
