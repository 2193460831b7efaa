// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Conversions between the C API's plain structs and the C++ types they mirror. Inline: they sit
/// on the path of every detection, and cj_detect may cost at most a few percent over the C++ call.
///
/// Enum values are cast: the C codes are the codes of the library's enum tables, which never
/// change once released (enum_table.hpp).

#include <sstream>
#include <string>

#include "clearjoint/clearjoint.h"
#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/contact_scenario.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "clearjoint/validation_error.hpp"
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

inline void copy_crossing(const geo::RimCrossing& from, cj_crossing& to) {
  to.angle = from.angle;
  to.angle_error_bound = from.angle_error;
  copy_vector(from.point, to.point);
  to.point_error_bound = from.point_error;
  to.multiplicity = from.multiplicity;
}

inline cj_arc arc_of(const geo::RimArc& a) { return {a.begin, a.end, a.full ? 1 : 0, 0}; }

inline void copy_contact(const geo::Contact& from, cj_contact& to) {
  to.type = code_of(from.type);
  to.base = code_of(from.base);
  copy_vector(from.p_WCj, to.p_WCj);
  copy_vector(from.p_WCi, to.p_WCi);
  copy_vector(from.normal_W, to.normal_W);
  to.depth = from.depth;
  to.depth_error_bound = from.depth_error;
  to.p_WCj_error_bound = from.p_WCj_error;
  to.p_WCi_error_bound = from.p_WCi_error;
  // Both, as the kernel sets both (those past crossing_count hold its default crossing).
  copy_crossing(from.crossings[0], to.crossings[0]);
  copy_crossing(from.crossings[1], to.crossings[1]);
  to.crossing_count = from.crossing_count;
  to.certificate = certificate_of(from.certificate);
}

/// Scenario, aligned, certificate, count and contacts[0, contact_count), as the C++ in-place
/// overload writes them; the contacts after them are left alone, and so are the reserved
/// members (clearjoint.h: unspecified in results; writing them measured ~2 ns a call).
inline void copy_result(const geo::JointContacts& from, cj_result& to) {
  to.scenario = code_of(from.scenario);
  to.aligned = from.aligned ? 1 : 0;
  to.contact_count = from.contact_count;
  to.certificate = certificate_of(from.certificate);
  for (int k = 0; k < from.contact_count; ++k) copy_contact(from.contacts[k], to.contacts[k]);
}

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
