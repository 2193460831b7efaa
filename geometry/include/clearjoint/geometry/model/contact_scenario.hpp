// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The contact scenarios of the paper's Fig. 2, (a) to (l), plus free flight and "beyond the
/// model", and the rule that names the scenario from the contacts found.

#include <array>
#include <string_view>

#include "clearjoint/geometry/model/enum_table.hpp"

namespace clearjoint::geometry {

/// Fig. 2 of Marques et al. (2017). Misaligned axes: (a)-(i); parallel axes: (j)-(l).
enum class ContactScenario {
  none,                             ///< free flight: no contact
  single_radial,                    ///< (a) one rim against the lateral wall
  single_axial,                     ///< (b) one rim against a base
  radial_at_both_bases,             ///< (c) both rims against the wall
  axial_at_both_bases,              ///< (d) rim A against base A and rim B against base B
  radial_and_axial_same_base,       ///< (e) one rim against the wall and the base on its side
  radial_and_axial_opposite_bases,  ///< (f) one rim against the wall, the other against its base
  two_radial_one_axial,             ///< (g) both rims against the wall, one against a base
  one_radial_two_axial,             ///< (h) one rim against the wall, both against their bases
  all_four,                         ///< (i) both rims against the wall and their bases
  line,                             ///< (j) parallel axes, journal along the wall
  face,                             ///< (k) parallel axes, journal base flat on a bearing base
  line_and_face,                    ///< (l) (j) and (k) together
  /// A configuration the paper's model does not cover: a rim crossing the wall four times (two
  /// penetration arcs on one rim), a rim entirely beyond the wall or a base, or a penetration
  /// deeper than the clearance in its direction (radial cr, eq. 1; axial ca, eq. 2).
  beyond_model,
};

/// Keys: "none", the letter of the paper's Fig. 2 ("a" ... "l"), "beyond_model".
template <>
struct EnumTable<ContactScenario> {
  using S = ContactScenario;
  static constexpr std::string_view type_name = "ContactScenario";
  static constexpr auto entries = std::to_array<EnumEntry<S>>({
      {S::none, "none", "none", "none"},
      {S::single_radial, "single_radial", "a", "(a) single radial"},
      {S::single_axial, "single_axial", "b", "(b) single axial"},
      {S::radial_at_both_bases, "radial_at_both_bases", "c", "(c) radial at both bases"},
      {S::axial_at_both_bases, "axial_at_both_bases", "d", "(d) axial at both bases"},
      {S::radial_and_axial_same_base, "radial_and_axial_same_base", "e", "(e) radial and axial at the same base"},
      {S::radial_and_axial_opposite_bases, "radial_and_axial_opposite_bases", "f",
       "(f) radial and axial at opposite bases"},
      {S::two_radial_one_axial, "two_radial_one_axial", "g", "(g) two radial, one axial"},
      {S::one_radial_two_axial, "one_radial_two_axial", "h", "(h) one radial, two axial"},
      {S::all_four, "all_four", "i", "(i) all four"},
      {S::line, "line", "j", "(j) line"},
      {S::face, "face", "k", "(k) face"},
      {S::line_and_face, "line_and_face", "l", "(l) line and face"},
      {S::beyond_model, "beyond_model", "beyond_model", "beyond model"},
  });
};
static_assert(entries_in_code_order<ContactScenario>());

/// The scenario's key, the one spelling used by the command line's output, the C API and the
/// docs: "none", the letter of the paper's Fig. 2 ("a" ... "l"), or "beyond_model".
std::string_view to_string(ContactScenario scenario) noexcept;

/// A label for people: "(a) single radial", "(j) line", "none", "beyond model", ...
std::string_view label(ContactScenario scenario) noexcept;

/// Which of the candidate contacts exist. Misaligned: radial_at_a/b (rim vs wall) and
/// axial_at_a/b (rim vs base plane). Parallel axes: line (radial at mid-length) and
/// axial_at_a/b (face contact).
struct ContactPresence {
  bool aligned = false;
  bool radial_at_a = false;
  bool radial_at_b = false;
  bool line = false;
  bool axial_at_a = false;
  bool axial_at_b = false;
  bool beyond_model = false;
};

/// The scenario named by a set of contacts: beyond_model wins over everything; then the counts
/// of radial and axial contacts (and for one of each, whether they share a base) pick (a)-(i) or
/// (j)-(l). A presence pattern no scenario describes (a line contact with misaligned axes, or
/// face contacts at both bases) is beyond_model.
ContactScenario classify_scenario(const ContactPresence& presence) noexcept;

}  // namespace clearjoint::geometry
