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
/// A visitor is called as visitor(key, value) with, for each kind of field:
///   plain     a reference to the member (double, int, bool, Vector3, an enum, Certificate,
///             PlaneSide, RimArc)
///   ErrorBound<D>       an error bound in metres or radians (kNoErrorBound when none is known)
///   FieldList<A, C>     an array and the member counting its entries in use
///   OptionalField<V, F> a value and the flag saying whether it is present
/// with the constness of the result visited (const results for writers, non-const for readers).

#include <cstddef>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "clearjoint/geometry/certificate.hpp"
#include "clearjoint/geometry/detect_contacts.hpp"
#include "clearjoint/geometry/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/intersect_circle_plane.hpp"
#include "clearjoint/geometry/rim_arc.hpp"

namespace clearjoint::geometry {

/// An error bound (D is double or const double).
template <class D>
struct ErrorBound {
  D& value;
};

/// items[0, count) are in use.
template <class Array, class Count>
struct FieldList {
  Array& items;
  Count& count;
};

/// `value` means something only when `present`.
template <class Value, class Flag>
struct OptionalField {
  Value& value;
  Flag& present;
};

namespace fields {

// One entry of a field list: a key and the member(s) it reads. `members` is how many members of
// the struct the entry covers.
template <class S, class M>
struct Plain {
  std::string_view key;
  M S::*member;
  static constexpr int members = 1;
  template <class R>
  constexpr auto view(R& r) const -> decltype((r.*member)) { return r.*member; }
};

template <class S>
struct Bound {
  std::string_view key;
  double S::*member;
  static constexpr int members = 1;
  template <class R>
  constexpr auto view(R& r) const {
    return ErrorBound<std::remove_reference_t<decltype(r.*member)>>{r.*member};
  }
};

template <class S, class A>
struct List {
  std::string_view key;
  A S::*items;
  int S::*count;
  static constexpr int members = 2;
  template <class R>
  constexpr auto view(R& r) const {
    return FieldList<std::remove_reference_t<decltype(r.*items)>, std::remove_reference_t<decltype(r.*count)>>{
        r.*items, r.*count};
  }
};

template <class S, class V>
struct Optional {
  std::string_view key;
  V S::*value;
  bool S::*present;
  static constexpr int members = 2;
  template <class R>
  constexpr auto view(R& r) const {
    return OptionalField<std::remove_reference_t<decltype(r.*value)>,
                         std::remove_reference_t<decltype(r.*present)>>{r.*value, r.*present};
  }
};

template <class S, class M>
constexpr Plain<S, M> plain(std::string_view key, M S::*member) { return {key, member}; }
template <class S>
constexpr Bound<S> bound(std::string_view key, double S::*member) { return {key, member}; }
template <class S, class A>
constexpr List<S, A> list(std::string_view key, A S::*items, int S::*count) { return {key, items, count}; }
template <class S, class V>
constexpr Optional<S, V> optional(std::string_view key, V S::*value, bool S::*present) {
  return {key, value, present};
}

}  // namespace fields

/// Specialised for each public result below: `static constexpr std::tuple fields`.
template <class Result>
struct ResultFields;

template <class Result>
concept DescribedResult = requires { ResultFields<std::remove_const_t<Result>>::fields; };

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

/// Call visitor(key, view) for each field of `result`, in the list's order.
template <DescribedResult Result, class Visitor>
constexpr void visit_fields(Result& result, Visitor&& visitor) {
  std::apply([&](const auto&... field) { (visitor(field.key, field.view(result)), ...); },
             ResultFields<std::remove_const_t<Result>>::fields);
}

namespace detail {

/// Converts to anything, in unevaluated operands only: how many of these an aggregate's braces
/// take is its member count.
struct AnyMember {
  template <class T>
  operator T() const;
};

template <class T, class... Members>
constexpr int aggregate_member_count() {
  if constexpr (requires { T{Members{}..., AnyMember{}}; }) {
    return aggregate_member_count<T, Members..., AnyMember>();
  } else {
    return static_cast<int>(sizeof...(Members));
  }
}

template <class Result>
constexpr int listed_member_count() {
  return std::apply([](const auto&... field) { return (0 + ... + field.members); },
                    ResultFields<Result>::fields);
}

template <class Result>
constexpr bool lists_every_member() {
  return listed_member_count<Result>() == aggregate_member_count<Result>();
}

}  // namespace detail

// A member added to one of these structs needs its line in the struct's field list above.
static_assert(detail::lists_every_member<Certificate>(), "a member of Certificate is missing from its field list");
static_assert(detail::lists_every_member<RimCrossing>(), "a member of RimCrossing is missing from its field list");
static_assert(detail::lists_every_member<RimArc>(), "a member of RimArc is missing from its field list");
static_assert(detail::lists_every_member<Contact>(), "a member of Contact is missing from its field list");
static_assert(detail::lists_every_member<JointContacts>(), "a member of JointContacts is missing from its field list");
static_assert(detail::lists_every_member<CirclePlaneIntersection>(), "a member of CirclePlaneIntersection is missing from its field list");
static_assert(detail::lists_every_member<CircleCylinderIntersection>(), "a member of CircleCylinderIntersection is missing from its field list");

}  // namespace clearjoint::geometry
