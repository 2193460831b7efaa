// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/model/contact_scenario.hpp"

namespace clearjoint::geometry {

std::string_view to_string(ContactScenario scenario) noexcept { return key_of(scenario); }

std::string_view label(ContactScenario scenario) noexcept { return label_of(scenario); }

ContactScenario classify_scenario(const ContactPresence& presence) noexcept {
  if (presence.beyond_model) return ContactScenario::beyond_model;
  const int axial = int(presence.axial_at_a) + int(presence.axial_at_b);
  if (presence.aligned) {
    if (presence.radial_at_a || presence.radial_at_b || axial > 1) {
      return ContactScenario::beyond_model;
    }
    if (presence.line) return axial == 1 ? ContactScenario::line_and_face : ContactScenario::line;
    return axial == 1 ? ContactScenario::face : ContactScenario::none;
  }
  if (presence.line) return ContactScenario::beyond_model;
  const int radial = int(presence.radial_at_a) + int(presence.radial_at_b);
  switch (radial * 3 + axial) {
    case 0: return ContactScenario::none;
    case 1: return ContactScenario::single_axial;
    case 2: return ContactScenario::axial_at_both_bases;
    case 3: return ContactScenario::single_radial;
    case 4:
      return presence.radial_at_a == presence.axial_at_a
                 ? ContactScenario::radial_and_axial_same_base
                 : ContactScenario::radial_and_axial_opposite_bases;
    case 5: return ContactScenario::one_radial_two_axial;
    case 6: return ContactScenario::radial_at_both_bases;
    case 7: return ContactScenario::two_radial_one_axial;
    default: return ContactScenario::all_four;
  }
}

}  // namespace clearjoint::geometry
