// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Contact detection in the pin-in-hole joint (model/pin_in_hole_dimensions.hpp): the paper's
/// kernel queries with the roles turned around. docs/contact-detection.md, "The pin-in-hole
/// joint", derives it.
///
/// Misaligned axes, per link face X (A: the face a_i points to, B the other):
///   edge at X: the hole's edge circle at X (body i) against the pin's lateral cylinder (body j),
///     intersect_circle_cylinder with circle = edge, cylinder = pin; the contact is where the edge
///     lies strictly inside the pin (the complement of the query's penetration arcs);
///   stop at X: the stop facing X against the link face X: the deepest point of the stop's face
///     less the hole, which is the outer circle's deepest point against the face plane
///     (intersect_circle_plane) where that point lies over the link, else the hole's edge circle's
///     deepest point into the stop's plane where that lies within the stop's rim; where neither
///     does (a corner of the two circles) the answer is beyond the model.
/// Parallel axes (eq. 5, decided exactly, or within DetectionOptions::parallel_angle_tolerance):
///   a line contact along the bore (the hole's mid-length circle against the pin) and face
///   contacts (a stop's outer circle wholly beyond its link face).
///
/// Contact (detect_contacts.hpp) is reused as it is: body i is the link (the bearing), body j the
/// pin (the journal); p_WCj is on the pin, p_WCi on the link, normal_W = (p_WCj - p_WCi)/depth,
/// the direction the pin penetrates the link, and the force on the pin acts along -normal_W.
/// type radial: an edge or line contact; axial: a stop. base a, b: at link face A or B; mid: the
/// line contact. crossings: those bounding the contact's arc, on the circle that bounds it (the
/// hole's edge circle, or the stop's outer circle), in that circle's frame (primitives.hpp).

#include <array>
#include <string_view>
#include <tuple>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/detection_options.hpp"
#include "clearjoint/geometry/model/field_lists.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/geometry/model/pin_in_hole_dimensions.hpp"
#include "clearjoint/geometry/model/pin_in_hole_scenario.hpp"

namespace clearjoint::geometry {

/// Two edge contacts per edge (beyond the model an edge can dip into the pin twice) and one stop
/// contact per face.
inline constexpr int kMaxPinInHoleContacts = 6;

struct PinInHoleContacts {
  PinInHoleScenario scenario = PinInHoleScenario::none;
  /// Axes parallel: exactly (eq. 5) or within DetectionOptions::parallel_angle_tolerance.
  bool aligned = false;
  /// Every contact found, radial (edges, line) before axial (stops, faces), face A before B. Also
  /// filled when scenario == beyond_model.
  std::array<Contact, kMaxPinInHoleContacts> contacts{};
  int contact_count = 0;
  /// The weakest certificate over every decision taken, including the "no contact" answers.
  Certificate certificate{};
};

/// Its field list (model/field_lists.hpp): a member added above needs its line here.
template <>
struct ResultFields<PinInHoleContacts> {
  using J = PinInHoleContacts;
  static constexpr std::string_view type_name = "PinInHoleContacts";
  static constexpr std::tuple fields{
      fields::plain("scenario", &J::scenario),
      fields::plain("aligned", &J::aligned, "axes parallel (exactly, eq. 5, or within parallel_angle_tolerance)"),
      fields::plain("certificate", &J::certificate, "the weakest over every decision taken, including 'no contact'"),
      fields::list("contacts", &J::contacts, &J::contact_count, "radial before axial, face A before B")};
};
static_assert(detail::lists_every_member<PinInHoleContacts>(),
              "a member of PinInHoleContacts is missing from its field list");

/// Detect every contact between a pin (pose `pin`: P, the pin point at the hole's centre when
/// centred, and its axis) and the hole it passes through (pose `hole`: the hole's centre, midway
/// between the link's faces, and its axis). Validates its inputs (InvalidInput names the field:
/// "dimensions.pin_radius", "hole.axis_W", "pin.p_WP", "options.parallel_angle_tolerance").
PinInHoleContacts detect_pin_in_hole_contacts(const PinInHoleDimensions& dimensions, const PartPose& hole,
                                              const PartPose& pin, const DetectionOptions& options = {});

}  // namespace clearjoint::geometry
