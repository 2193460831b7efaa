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
  static constexpr std::string_view type_name = "Certificate";
  static constexpr std::tuple fields{
      fields::plain("level", &C::level),
      fields::plain("reason", &C::reason, "A CertificateReason to branch on; none for certified answers.")};
};

template <>
struct ResultFields<RimCrossing> {
  using X = RimCrossing;
  static constexpr std::string_view type_name = "RimCrossing";
  static constexpr std::tuple fields{
      fields::plain("angle", &X::angle, "rim angle in [0, 2 pi), radians"),
      fields::bound("angle_error", &X::angle_error),
      fields::plain("point", &X::point, "world frame, shape (3,)"),
      fields::bound("point_error", &X::point_error),
      fields::plain("multiplicity", &X::multiplicity, "1 crossing, 2 tangency, 3-4 higher-order contact")};
};

template <>
struct ResultFields<RimArc> {
  static constexpr std::string_view type_name = "RimArc";
  static constexpr std::tuple fields{fields::plain("begin", &RimArc::begin), fields::plain("end", &RimArc::end),
                                     fields::plain("full", &RimArc::full)};
};

/// The keys of the command line and of Python: "point_journal" is p_WCj, "normal" normal_W.
template <>
struct ResultFields<Contact> {
  using C = Contact;
  static constexpr std::string_view type_name = "Contact";
  static constexpr std::tuple fields{
      fields::plain("type", &C::type),
      fields::plain("base", &C::base),
      fields::plain("depth", &C::depth, "penetration depth >= 0"),
      fields::bound("depth_error", &C::depth_error, "bound on the depth's error; certified unless uncertain (then inf)"),
      fields::plain("point_journal", &C::p_WCj, "C_j on the journal (eqs. 8, 10, 14, 19)"),
      fields::plain("point_bearing", &C::p_WCi, "C_i on the bearing (eqs. 7, 9, 15, 21)"),
      fields::bound("point_journal_error", &C::p_WCj_error, "bound on point_journal's error (Euclidean)"),
      fields::bound("point_bearing_error", &C::p_WCi_error, "bound on point_bearing's error (Euclidean)"),
      fields::plain("normal", &C::normal_W, "unit normal, out of the bearing"),
      fields::list("crossings", &C::crossings, &C::crossing_count,
                   "the rim crossings bounding the penetration arc (none for line and face contacts)"),
      fields::plain("certificate", &C::certificate)};
};

template <>
struct ResultFields<JointContacts> {
  using J = JointContacts;
  static constexpr std::string_view type_name = "JointContacts";
  static constexpr std::tuple fields{
      fields::plain("scenario", &J::scenario),
      fields::plain("aligned", &J::aligned, "axes parallel (exactly, eq. 5, or within parallel_angle_tolerance)"),
      fields::plain("certificate", &J::certificate, "the weakest over every decision taken, including 'no contact'"),
      fields::list("contacts", &J::contacts, &J::contact_count, "radial before axial, base A before B")};
};

template <>
struct ResultFields<CirclePlaneIntersection> {
  using P = CirclePlaneIntersection;
  static constexpr std::string_view type_name = "CirclePlaneIntersection";
  static constexpr std::tuple fields{
      fields::plain("topology", &P::topology),
      fields::plain("side", &P::side,
                    "PlaneSide as an int. +1: the circle lies on the side the plane normal points to, -1 the "
                    "other; 0 for two_crossings and circle_in_plane"),
      fields::list("crossings", &P::crossings, &P::crossing_count),
      fields::optional("penetration", &P::penetration, &P::has_penetration,
                       "the rim points strictly on the normal's side (a RimArc), or None"),
      fields::plain("max_signed_distance", &P::max_signed_distance,
                    "largest signed distance of a rim point from the plane, positive on the normal's side"),
      fields::bound("max_signed_distance_error", &P::max_signed_distance_error),
      fields::plain("certificate", &P::certificate)};
};

template <>
struct ResultFields<CircleCylinderIntersection> {
  using Y = CircleCylinderIntersection;
  static constexpr std::string_view type_name = "CircleCylinderIntersection";
  static constexpr std::tuple fields{
      fields::plain("topology", &Y::topology),
      fields::list("crossings", &Y::crossings, &Y::crossing_count, "sorted by angle; multiplicities add up to 0, 2 or 4"),
      fields::list("penetration_arcs", &Y::penetration_arcs, &Y::arc_count,
                   "maximal arcs strictly beyond the wall; two arcs are beyond the paper's model"),
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
