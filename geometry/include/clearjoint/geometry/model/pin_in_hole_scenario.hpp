// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The contact scenarios of the pin-in-hole joint (pin_in_hole_dimensions.hpp), the counterpart
/// of the paper's Fig. 2 for a pin longer than its hole: docs/contact-detection.md, "The
/// pin-in-hole joint", has the table.

#include <array>
#include <string_view>

#include "clearjoint/geometry/model/enum_table.hpp"

namespace clearjoint::geometry {

/// Misaligned axes: edge contacts (a hole edge circle inside the pin's lateral surface) and stop
/// contacts (a stop against a link face, at a point); parallel axes: a line contact along the bore
/// and a face contact (a stop flush on a link face).
enum class PinInHoleScenario {
  none,                   ///< free: no contact
  one_edge,               ///< one hole edge against the pin (edge loading)
  both_edges_opposite,    ///< both edges, at opposite sides of the pin (a tilted pin across the hole)
  both_edges_same_side,   ///< both edges, on one side of the pin (an offset pin barely tilted)
  line,                   ///< parallel axes, the pin along the bore
  one_stop,               ///< a stop against its link face, at a point
  both_stops,             ///< both stops against their faces, at points
  face,                   ///< parallel axes, a stop flush on its link face
  edges_and_stops,        ///< misaligned: edge contacts and stop contacts together
  line_and_face,          ///< parallel axes: line and face together
  /// A configuration the model does not cover: the pin's axis outside the hole (or parallel to
  /// the link's faces), a hole edge dipping into the pin twice, a stop whose deepest point is at a
  /// corner of its rim and the hole's edge, or a penetration deeper than the clearance in its
  /// direction (radial cr; axial ca with two stops, L/2 with one), or face contacts at both faces.
  beyond_model,
};

template <>
struct EnumTable<PinInHoleScenario> {
  using S = PinInHoleScenario;
  static constexpr std::string_view type_name = "PinInHoleScenario";
  static constexpr auto entries = std::to_array({
      named_entry(S::none, "none", "none"),
      named_entry(S::one_edge, "one_edge", "one hole edge against the pin"),
      named_entry(S::both_edges_opposite, "both_edges_opposite", "both hole edges, at opposite sides (tilt)"),
      named_entry(S::both_edges_same_side, "both_edges_same_side", "both hole edges, on one side"),
      named_entry(S::line, "line", "aligned: line contact along the bore"),
      named_entry(S::one_stop, "one_stop", "one stop against its link face"),
      named_entry(S::both_stops, "both_stops", "both stops against their link faces"),
      named_entry(S::face, "face", "aligned: a stop flush on its link face"),
      named_entry(S::edges_and_stops, "edges_and_stops", "edge and stop contacts together"),
      named_entry(S::line_and_face, "line_and_face", "aligned: line and face together"),
      named_entry(S::beyond_model, "beyond_model", "beyond model"),
  });
};
static_assert(entries_in_code_order<PinInHoleScenario>());

/// The key: "none", "one_edge", ..., "beyond_model" (the enumerators' names).
constexpr std::string_view to_string(PinInHoleScenario scenario) noexcept { return key_of(scenario); }
/// A label for people.
constexpr std::string_view label(PinInHoleScenario scenario) noexcept { return label_of(scenario); }

}  // namespace clearjoint::geometry
