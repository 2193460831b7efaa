// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The C member of each field of the results clearjoint.h mirrors, in the C struct's order:
/// CMembers<R>::members[i] is where field CMembers<R>::fields[i] of ResultFields<R>::fields goes
/// in the C struct CMembers<R>::type. conversions.hpp copies a result by pairing the two. The block below is
/// written from the C layouts (scripts/projections/c_copies.py, c_structs.py) by
/// `cmake --build build --target projections`; projections.up_to_date fails while it is stale.

#include <cstddef>
#include <cstdint>
#include <tuple>

#include "clearjoint/clearjoint.h"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"
#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/rim_arc.hpp"

namespace clearjoint::c_api {

/// A list whose entries [0, count) are written; the C struct leaves the others as they were.
template <class Items, class S>
struct InUse {
  Items S::*items;
  int32_t S::*count;
};

/// A list written whole (its unused entries hold the kernel's defaults), and its count.
template <class Items, class S>
struct Whole {
  Items S::*items;
  int32_t S::*count;
};

// Deduction guides: Clang before 17 does not deduce an aggregate's template arguments (P1816).
template <class Items, class S>
InUse(Items S::*, int32_t S::*) -> InUse<Items, S>;
template <class Items, class S>
Whole(Items S::*, int32_t S::*) -> Whole<Items, S>;

template <class Result>
struct CMembers;

// BEGIN GENERATED c members
template <>
struct CMembers<geometry::Certificate> {
  using type = cj_certificate;
  static constexpr std::size_t fields[] = {0, 1};
  static constexpr std::tuple members{
      &cj_certificate::level,
      &cj_certificate::reason};
};
template <>
struct CMembers<geometry::RimCrossing> {
  using type = cj_crossing;
  static constexpr std::size_t fields[] = {0, 1, 2, 3, 4};
  static constexpr std::tuple members{
      &cj_crossing::angle,
      &cj_crossing::angle_error_bound,
      &cj_crossing::point,
      &cj_crossing::point_error_bound,
      &cj_crossing::multiplicity};
};
template <>
struct CMembers<geometry::Contact> {
  using type = cj_contact;
  static constexpr std::size_t fields[] = {0, 1, 4, 5, 8, 2, 3, 6, 7, 9, 10};
  static constexpr std::tuple members{
      &cj_contact::type,
      &cj_contact::base,
      &cj_contact::p_WCj,
      &cj_contact::p_WCi,
      &cj_contact::normal_W,
      &cj_contact::depth,
      &cj_contact::depth_error_bound,
      &cj_contact::p_WCj_error_bound,
      &cj_contact::p_WCi_error_bound,
      Whole{&cj_contact::crossings, &cj_contact::crossing_count},
      &cj_contact::certificate};
};
template <>
struct CMembers<geometry::JointContacts> {
  using type = cj_result;
  static constexpr std::size_t fields[] = {0, 1, 2, 3};
  static constexpr std::tuple members{
      &cj_result::scenario,
      &cj_result::aligned,
      &cj_result::certificate,
      InUse{&cj_result::contacts, &cj_result::contact_count}};
};
template <>
struct CMembers<geometry::PinInHoleContacts> {
  using type = cj_pin_in_hole_result;
  static constexpr std::size_t fields[] = {0, 1, 2, 3};
  static constexpr std::tuple members{
      &cj_pin_in_hole_result::scenario,
      &cj_pin_in_hole_result::aligned,
      &cj_pin_in_hole_result::certificate,
      InUse{&cj_pin_in_hole_result::contacts, &cj_pin_in_hole_result::contact_count}};
};
// END GENERATED c members

}  // namespace clearjoint::c_api
