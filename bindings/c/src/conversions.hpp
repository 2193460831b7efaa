// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Conversions between the C API's plain structs and the C++ types they mirror. Inline: they sit
/// on the path of every detection, and cj_detect may cost at most a few percent over the C++ call.
///
/// Enum values are cast: the C codes are the codes of the library's enum tables, which never
/// change once released (enum_table.hpp).

#include <array>
#include <cstddef>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "clearjoint/clearjoint.h"
#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/contact_scenario.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "clearjoint/validation_error.hpp"
#include "c_members.hpp"
#include "status_reporting.hpp"

namespace clearjoint::c_api {

namespace geo = clearjoint::geometry;

/// Through Eigen::Map rather than Vector3(v[0], v[1], v[2]): GCC writes the latter's copy with
/// stores the kernel's first loads cannot forward from, which cost ~14 ns a free-flight
/// detection (~50 ns) in bench_c_api; the Map copy measured no cost.
inline geo::Vector3 vector_of(const double (&v)[3]) { return Eigen::Map<const geo::Vector3>(v); }

inline void copy_vector(const geo::Vector3& from, double (&to)[3]) {
  to[0] = from.x();
  to[1] = from.y();
  to[2] = from.z();
}

inline geo::JointDimensions dimensions_of(const cj_dimensions& d) {
  return {d.bearing_radius, d.bearing_length, d.journal_radius, d.journal_length};
}

inline geo::PartPose pose_of(const cj_pose& p) {
  return {Eigen::Map<const geo::Vector3>(p.p_WP), Eigen::Map<const geo::Vector3>(p.axis_W)};
}

/// Throw ValidationError naming the first nonzero reserved field of `options`. Defined here so that
/// the tests of these conversions link without the library's internals; never inlined, so that
/// cj_detect's path stays as small as it was.
[[noreturn, gnu::cold, gnu::noinline]] inline void reject_reserved(const cj_options& options) {
  for (int k = 0; k < 4; ++k) {
    if (options.reserved[k] != 0.0) {
      std::ostringstream message;
      message.precision(17);
      message << " = " << options.reserved[k]
              << ": must be 0 (start from cj_default_options() or a zero-initialised struct)";
      throw ValidationError("options.reserved[" + std::to_string(k) + "]", message.str());
    }
  }
  throw ValidationError("options.reserved", ": must be 0");
}

/// The kernel's options from the caller's (defaults for NULL); rejects a nonzero reserved field
/// (a field of a later version of the API). The range of parallel_angle_tolerance is the
/// kernel's to check.
inline geo::DetectionOptions detection_options_of(const cj_options* options) {
  geo::DetectionOptions out;
  if (options == nullptr) return out;
  if ((options->reserved[0] != 0.0) | (options->reserved[1] != 0.0) | (options->reserved[2] != 0.0) |
      (options->reserved[3] != 0.0)) {
    reject_reserved(*options);
  }
  out.intersection.certify = options->certify != 0;
  out.intersection.exact_fallback = options->exact_fallback != 0;
  out.parallel_angle_tolerance = options->parallel_angle_tolerance;
  return out;
}

/// The caller's options for the kernel's (cj_default_options: the defaults); reserved fields 0.
/// detection_options_of(&options_of(o)) gives `o` back, which
/// tests/bindings/c/test_c_descriptions.cpp checks one option at a time.
inline cj_options options_of(const geo::DetectionOptions& options) {
  cj_options out{};
  out.certify = options.intersection.certify ? 1 : 0;
  out.exact_fallback = options.intersection.exact_fallback ? 1 : 0;
  out.parallel_angle_tolerance = options.parallel_angle_tolerance;
  return out;
}

/// The C code of a C++ enum value: the value's code in its table (enum_table.hpp), which the C
/// header's constants repeat; tests/bindings/c/test_c_descriptions.cpp checks that they agree.
template <geo::TabledEnum E>
inline int32_t code_of(E value) {
  return static_cast<int32_t>(value);
}

/// The reason's sentence is read from the library's table, which is inline (a copy in this
/// library): calling the kernel library for it on every certificate was an out-of-line call
/// across libraries, ~2 ns of a free-flight cj_detect.
inline cj_certificate certificate_of(const geo::Certificate& c) {
  const int32_t reason = code_of(c.reason);
  return {code_of(c.level), reason,
          geo::EnumTable<geo::CertificateReason>::entries[static_cast<std::size_t>(reason)].label.data()};
}

/// The C value of a field, by its type: a double or int as it is, a bool 1 or 0, an enum its code,
/// a vector its three components, a certificate with its sentence, a result its C struct.
inline void copy_value(double from, double& to) { to = from; }
inline void copy_value(int from, int32_t& to) { to = from; }
inline void copy_value(bool from, int32_t& to) { to = from ? 1 : 0; }
template <geo::TabledEnum E>
inline void copy_value(E from, int32_t& to) {
  to = code_of(from);
}
inline void copy_value(const geo::Vector3& from, double (&to)[3]) { copy_vector(from, to); }
inline void copy_value(const geo::Certificate& from, cj_certificate& to) { to = certificate_of(from); }
template <class Result>
  requires requires { typename CMembers<Result>::type; }
inline void copy_value(const Result& from, typename CMembers<Result>::type& to);

/// One field into its C member, by the field's kind (model/field_lists.hpp).
template <class S, class M, class C, class T>
inline void copy_field(const geo::fields::Plain<S, M>& field, T C::*member, const S& from, C& to) {
  copy_value(from.*field.member, to.*member);
}
template <class S, class C>
inline void copy_field(const geo::fields::Bound<S>& field, double C::*member, const S& from, C& to) {
  to.*member = from.*field.member;
}
/// Whole: every entry and the count (the entries past the count hold the kernel's defaults).
template <class S, class A, class Items, class C>
inline void copy_field(const geo::fields::List<S, A>& field, const Whole<Items, C>& members, const S& from, C& to) {
  static_assert(std::tuple_size_v<A> == std::extent_v<Items>, "a list and its C array differ in capacity");
  for (std::size_t k = 0; k < std::tuple_size_v<A>; ++k) copy_value((from.*field.items)[k], (to.*members.items)[k]);
  to.*members.count = from.*field.count;
}
/// InUse: entries [0, count) only, as the C++ in-place overloads write them.
template <class S, class A, class Items, class C>
inline void copy_field(const geo::fields::List<S, A>& field, const InUse<Items, C>& members, const S& from, C& to) {
  static_assert(std::tuple_size_v<A> == std::extent_v<Items>, "a list and its C array differ in capacity");
  const int count = from.*field.count;
  to.*members.count = count;
  for (int k = 0; k < count; ++k) copy_value((from.*field.items)[k], (to.*members.items)[k]);
}

/// Every field of a result into its C struct, front to back: each C member (c_members.hpp,
/// generated from the C layouts, in the struct's order) paired with its field of the list. The
/// members no field names (padding, reserved room) are left alone (clearjoint.h: unspecified in
/// results; writing them measured ~2 ns a call).
template <class Result>
  requires requires { typename CMembers<Result>::type; }
inline void copy_value(const Result& from, typename CMembers<Result>::type& to) {
  constexpr const auto& fields = geo::ResultFields<Result>::fields;
  constexpr const auto& members = CMembers<Result>::members;
  static_assert(std::tuple_size_v<std::remove_cvref_t<decltype(fields)>> ==
                    std::tuple_size_v<std::remove_cvref_t<decltype(members)>>,
                "c_members.hpp is stale: cmake --build build --target projections");
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (copy_field(std::get<CMembers<Result>::fields[I]>(fields), std::get<I>(members), from, to), ...);
  }(std::make_index_sequence<std::tuple_size_v<std::remove_cvref_t<decltype(fields)>>>{});
}

inline void copy_crossing(const geo::RimCrossing& from, cj_crossing& to) { copy_value(from, to); }

inline cj_arc arc_of(const geo::RimArc& a) { return {a.begin, a.end, a.full ? 1 : 0, 0}; }

/// Both crossings, as the kernel sets both (those past crossing_count hold its default crossing).
inline void copy_contact(const geo::Contact& from, cj_contact& to) { copy_value(from, to); }

/// Scenario, aligned, certificate, count and contacts[0, contact_count), as the C++ in-place
/// overload writes them; the contacts after them are left alone, and so are the reserved members.
inline void copy_result(const geo::JointContacts& from, cj_result& to) { copy_value(from, to); }

/// The kernel queries' answers; the reserved members are zero.
inline cj_circle_plane_result circle_plane_result_of(const geo::CirclePlaneIntersection& found) {
  cj_circle_plane_result out{};
  out.topology = code_of(found.topology);
  out.side = static_cast<int32_t>(found.side);  // PlaneSide's values are -1, 0, +1
  for (int k = 0; k < 2; ++k) copy_crossing(found.crossings[k], out.crossings[k]);
  out.crossing_count = found.crossing_count;
  out.has_penetration = found.has_penetration ? 1 : 0;
  out.penetration = arc_of(found.penetration);
  out.max_signed_distance = found.max_signed_distance;
  out.max_signed_distance_error_bound = found.max_signed_distance_error;
  out.certificate = certificate_of(found.certificate);
  return out;
}

inline cj_circle_cylinder_result circle_cylinder_result_of(const geo::CircleCylinderIntersection& found) {
  cj_circle_cylinder_result out{};
  out.topology = code_of(found.topology);
  for (int k = 0; k < 4; ++k) copy_crossing(found.crossings[k], out.crossings[k]);
  out.crossing_count = found.crossing_count;
  for (int k = 0; k < 2; ++k) out.penetration_arcs[k] = arc_of(found.penetration_arcs[k]);
  out.arc_count = found.arc_count;
  out.certificate = certificate_of(found.certificate);
  return out;
}

}  // namespace clearjoint::c_api
