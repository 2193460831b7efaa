// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// How a result's field list is written (joint/result_fields.hpp holds the lists): the kinds of
/// field a visitor sees, the entries of a list, visit_fields, and the member count of an
/// aggregate, by which the compiler checks that a list covers every member of its struct.
///
/// A visitor is called as visitor(key, value) with, for each kind of field:
///   plain     a reference to the member (double, int, bool, Vector3, an enum, Certificate,
///             PlaneSide, RimArc)
///   ErrorBound<D>       an error bound in metres or radians (kNoErrorBound when none is known)
///   FieldList<A, C>     an array and the member counting its entries in use
///   OptionalField<V, F> a value and the flag saying whether it is present
/// with the constness of the result visited (const results for writers, non-const for readers).

#include <string_view>
#include <tuple>
#include <type_traits>

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

// One entry of a field list: a key, the member(s) it reads and a phrase for people (the
// docstring of Python's attribute). `members` is how many members of the struct the entry covers.
template <class S, class M>
struct Plain {
  std::string_view key;
  M S::*member;
  std::string_view doc;
  static constexpr int members = 1;
  template <class R>
  constexpr auto view(R& r) const -> decltype((r.*member)) { return r.*member; }
};

template <class S>
struct Bound {
  std::string_view key;
  double S::*member;
  std::string_view doc;
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
  std::string_view doc;
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
  std::string_view doc;
  static constexpr int members = 2;
  template <class R>
  constexpr auto view(R& r) const {
    return OptionalField<std::remove_reference_t<decltype(r.*value)>,
                         std::remove_reference_t<decltype(r.*present)>>{r.*value, r.*present};
  }
};

template <class S, class M>
constexpr Plain<S, M> plain(std::string_view key, M S::*member, std::string_view doc = {}) {
  return {key, member, doc};
}
template <class S>
constexpr Bound<S> bound(std::string_view key, double S::*member, std::string_view doc = {}) {
  return {key, member, doc};
}
template <class S, class A>
constexpr List<S, A> list(std::string_view key, A S::*items, int S::*count, std::string_view doc = {}) {
  return {key, items, count, doc};
}
template <class S, class V>
constexpr Optional<S, V> optional(std::string_view key, V S::*value, bool S::*present, std::string_view doc = {}) {
  return {key, value, present, doc};
}

}  // namespace fields

/// Specialised for each public result (joint/result_fields.hpp): `static constexpr std::string_view
/// type_name` (the class name of the front-ends: Python, the stubs) and `static constexpr std::tuple
/// fields`.
template <class Result>
struct ResultFields;

template <class Result>
concept DescribedResult = requires { ResultFields<std::remove_const_t<Result>>::fields; };

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

}  // namespace clearjoint::geometry
