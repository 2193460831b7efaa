// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The field list of every public result: one list per type, in the order the outputs write the
/// fields, with the key each front-end spells them by. The command line's JSON and Python's
/// result dicts are written (and read back) through visit_fields; the front-ends that cannot be
/// (the C structs, the equivalence writers, the answer dumps of bench/geometry) are checked
/// against it by tests that change one field at a time and require the output to change.
///
/// The lists are checked by the compiler: each one must cover every member of its struct (the
/// static_asserts at the end count an aggregate's members), so a field added to Contact without
/// its line here does not build, and a front-end written through visit_fields gets it at once.
///
/// The kinds of field a visitor sees, and visit_fields itself: model/field_lists.hpp.

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/field_lists.hpp"
#include "clearjoint/geometry/model/rim_arc.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"

namespace clearjoint::geometry {

template <>
struct ResultFields<Certificate> {
  using C = Certificate;
  static constexpr std::tuple fields{fields::plain("level", &C::level), fields::plain("reason", &C::reason)};
};

template <>
struct ResultFields<RimCrossing> {
  using X = RimCrossing;
  static constexpr std::tuple fields{fields::plain("angle", &X::angle), fields::bound("angle_error", &X::angle_error),
                                     fields::plain("point", &X::point), fields::bound("point_error", &X::point_error),
                                     fields::plain("multiplicity", &X::multiplicity)};
};

template <>
struct ResultFields<RimArc> {
  static constexpr std::tuple fields{fields::plain("begin", &RimArc::begin), fields::plain("end", &RimArc::end),
                                     fields::plain("full", &RimArc::full)};
};

/// The keys of the command line and of Python: "point_journal" is p_WCj, "normal" normal_W.
template <>
struct ResultFields<Contact> {
  using C = Contact;
  static constexpr std::tuple fields{fields::plain("type", &C::type),
                                     fields::plain("base", &C::base),
                                     fields::plain("depth", &C::depth),
                                     fields::bound("depth_error", &C::depth_error),
                                     fields::plain("point_journal", &C::p_WCj),
                                     fields::plain("point_bearing", &C::p_WCi),
                                     fields::bound("point_journal_error", &C::p_WCj_error),
                                     fields::bound("point_bearing_error", &C::p_WCi_error),
                                     fields::plain("normal", &C::normal_W),
                                     fields::list("crossings", &C::crossings, &C::crossing_count),
                                     fields::plain("certificate", &C::certificate)};
};

template <>
struct ResultFields<JointContacts> {
  using J = JointContacts;
  static constexpr std::tuple fields{fields::plain("scenario", &J::scenario), fields::plain("aligned", &J::aligned),
                                     fields::plain("certificate", &J::certificate),
                                     fields::list("contacts", &J::contacts, &J::contact_count)};
};

template <>
struct ResultFields<CirclePlaneIntersection> {
  using P = CirclePlaneIntersection;
  static constexpr std::tuple fields{fields::plain("topology", &P::topology),
                                     fields::plain("side", &P::side),
                                     fields::list("crossings", &P::crossings, &P::crossing_count),
                                     fields::optional("penetration", &P::penetration, &P::has_penetration),
                                     fields::plain("max_signed_distance", &P::max_signed_distance),
                                     fields::bound("max_signed_distance_error", &P::max_signed_distance_error),
                                     fields::plain("certificate", &P::certificate)};
};

template <>
struct ResultFields<CircleCylinderIntersection> {
  using Y = CircleCylinderIntersection;
  static constexpr std::tuple fields{fields::plain("topology", &Y::topology),
                                     fields::list("crossings", &Y::crossings, &Y::crossing_count),
                                     fields::list("penetration_arcs", &Y::penetration_arcs, &Y::arc_count),
                                     fields::plain("certificate", &Y::certificate)};
};

// A member added to one of these structs needs its line in the struct's field list above.
static_assert(detail::lists_every_member<Certificate>(), "a member of Certificate is missing from its field list");
static_assert(detail::lists_every_member<RimCrossing>(), "a member of RimCrossing is missing from its field list");
static_assert(detail::lists_every_member<RimArc>(), "a member of RimArc is missing from its field list");
static_assert(detail::lists_every_member<Contact>(), "a member of Contact is missing from its field list");
static_assert(detail::lists_every_member<JointContacts>(), "a member of JointContacts is missing from its field list");
static_assert(detail::lists_every_member<CirclePlaneIntersection>(), "a member of CirclePlaneIntersection is missing from its field list");
static_assert(detail::lists_every_member<CircleCylinderIntersection>(), "a member of CircleCylinderIntersection is missing from its field list");

}  // namespace clearjoint::geometry
