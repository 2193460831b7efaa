// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/contact_scenario.hpp"

namespace clearjoint::geometry {

std::string_view to_string(ContactScenario scenario) noexcept {
  switch (scenario) {
    case ContactScenario::none: return "none";
    case ContactScenario::single_radial: return "a";
    case ContactScenario::single_axial: return "b";
    case ContactScenario::radial_at_both_bases: return "c";
    case ContactScenario::axial_at_both_bases: return "d";
    case ContactScenario::radial_and_axial_same_base: return "e";
    case ContactScenario::radial_and_axial_opposite_bases: return "f";
    case ContactScenario::two_radial_one_axial: return "g";
    case ContactScenario::one_radial_two_axial: return "h";
    case ContactScenario::all_four: return "i";
    case ContactScenario::line: return "j";
    case ContactScenario::face: return "k";
    case ContactScenario::line_and_face: return "l";
    case ContactScenario::beyond_model: return "beyond_model";
  }
  return "unknown";
}

std::string_view label(ContactScenario scenario) noexcept {
  switch (scenario) {
    case ContactScenario::none: return "none";
    case ContactScenario::single_radial: return "(a) single radial";
    case ContactScenario::single_axial: return "(b) single axial";
    case ContactScenario::radial_at_both_bases: return "(c) radial at both bases";
    case ContactScenario::axial_at_both_bases: return "(d) axial at both bases";
    case ContactScenario::radial_and_axial_same_base: return "(e) radial and axial at the same base";
    case ContactScenario::radial_and_axial_opposite_bases:
      return "(f) radial and axial at opposite bases";
    case ContactScenario::two_radial_one_axial: return "(g) two radial, one axial";
    case ContactScenario::one_radial_two_axial: return "(h) one radial, two axial";
    case ContactScenario::all_four: return "(i) all four";
    case ContactScenario::line: return "(j) line";
    case ContactScenario::face: return "(k) face";
    case ContactScenario::line_and_face: return "(l) line and face";
    case ContactScenario::beyond_model: return "beyond model";
  }
  return "unknown";
}

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
