// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Conversions between the C API's plain structs and the C++ types they mirror. Inline: they sit
/// on the path of every detection, and cj_detect may cost at most a few percent over the C++ call.
///
/// Enum values are mapped by switch, not cast, so that the C codes stay fixed (they are ABI)
/// whatever order the C++ enums take; each switch is an identity that the compiler folds away.

#include "clearjoint/clearjoint.h"
#include "clearjoint/geometry/certificate.hpp"
#include "clearjoint/geometry/contact_scenario.hpp"
#include "clearjoint/geometry/detect_contacts.hpp"
#include "clearjoint/geometry/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/intersect_circle_plane.hpp"
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

/// Throw InvalidInput naming the first nonzero reserved field of `options`.
[[noreturn]] void reject_reserved(const cj_options& options);

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

inline int32_t code_of(geo::ContactScenario s) {
  switch (s) {
    case geo::ContactScenario::none: return CJ_SCENARIO_NONE;
    case geo::ContactScenario::single_radial: return CJ_SCENARIO_SINGLE_RADIAL;
    case geo::ContactScenario::single_axial: return CJ_SCENARIO_SINGLE_AXIAL;
    case geo::ContactScenario::radial_at_both_bases: return CJ_SCENARIO_RADIAL_AT_BOTH_BASES;
    case geo::ContactScenario::axial_at_both_bases: return CJ_SCENARIO_AXIAL_AT_BOTH_BASES;
    case geo::ContactScenario::radial_and_axial_same_base: return CJ_SCENARIO_RADIAL_AND_AXIAL_SAME_BASE;
    case geo::ContactScenario::radial_and_axial_opposite_bases:
      return CJ_SCENARIO_RADIAL_AND_AXIAL_OPPOSITE_BASES;
    case geo::ContactScenario::two_radial_one_axial: return CJ_SCENARIO_TWO_RADIAL_ONE_AXIAL;
    case geo::ContactScenario::one_radial_two_axial: return CJ_SCENARIO_ONE_RADIAL_TWO_AXIAL;
    case geo::ContactScenario::all_four: return CJ_SCENARIO_ALL_FOUR;
    case geo::ContactScenario::line: return CJ_SCENARIO_LINE;
    case geo::ContactScenario::face: return CJ_SCENARIO_FACE;
    case geo::ContactScenario::line_and_face: return CJ_SCENARIO_LINE_AND_FACE;
    case geo::ContactScenario::beyond_model: return CJ_SCENARIO_BEYOND_MODEL;
  }
  return CJ_SCENARIO_BEYOND_MODEL;
}

inline int32_t code_of(geo::Certainty level) {
  switch (level) {
    case geo::Certainty::exact: return CJ_CERTAINTY_EXACT;
    case geo::Certainty::certified: return CJ_CERTAINTY_CERTIFIED;
    case geo::Certainty::uncertain: return CJ_CERTAINTY_UNCERTAIN;
  }
  return CJ_CERTAINTY_UNCERTAIN;
}

inline int32_t code_of(geo::ContactType type) {
  return type == geo::ContactType::radial ? CJ_CONTACT_RADIAL : CJ_CONTACT_AXIAL;
}

inline int32_t code_of(geo::ContactBase base) {
  switch (base) {
    case geo::ContactBase::a: return CJ_BASE_A;
    case geo::ContactBase::b: return CJ_BASE_B;
    case geo::ContactBase::mid: return CJ_BASE_MID;
  }
  return CJ_BASE_MID;
}

inline int32_t code_of(geo::CertificateReason reason) {
  using R = geo::CertificateReason;
  switch (reason) {
    case R::none: return CJ_REASON_NONE;
    case R::not_decided: return CJ_REASON_NOT_DECIDED;
    case R::certificate_switched_off: return CJ_REASON_CERTIFICATE_SWITCHED_OFF;
    case R::plane_filter_undecided: return CJ_REASON_PLANE_FILTER_UNDECIDED;
    case R::plane_filter_undecided_exact_fallback_off: return CJ_REASON_PLANE_FILTER_UNDECIDED_EXACT_FALLBACK_OFF;
    case R::plane_results_not_representable: return CJ_REASON_PLANE_RESULTS_NOT_REPRESENTABLE;
    case R::subdivision_budget_exhausted: return CJ_REASON_SUBDIVISION_BUDGET_EXHAUSTED;
    case R::more_than_four_roots: return CJ_REASON_MORE_THAN_FOUR_ROOTS;
    case R::interval_proof_failed_near_multiple_root: return CJ_REASON_INTERVAL_PROOF_FAILED_NEAR_MULTIPLE_ROOT;
    case R::coefficient_overflow: return CJ_REASON_COEFFICIENT_OVERFLOW;
    case R::cylinder_points_not_representable: return CJ_REASON_CYLINDER_POINTS_NOT_REPRESENTABLE;
    case R::exact_root_isolation_budget_exhausted: return CJ_REASON_EXACT_ROOT_ISOLATION_BUDGET_EXHAUSTED;
    case R::exact_coefficients_too_large: return CJ_REASON_EXACT_COEFFICIENTS_TOO_LARGE;
    case R::exact_intermediate_beyond_double_range: return CJ_REASON_EXACT_INTERMEDIATE_BEYOND_DOUBLE_RANGE;
    case R::contact_not_representable_in_world: return CJ_REASON_CONTACT_NOT_REPRESENTABLE_IN_WORLD;
    case R::axes_parallel_within_tolerance: return CJ_REASON_AXES_PARALLEL_WITHIN_TOLERANCE;
    case R::beyond_model_undecided: return CJ_REASON_BEYOND_MODEL_UNDECIDED;
  }
  return CJ_REASON_NOT_DECIDED;
}

/// The reasons C++ has, in order: cj_reason_string finds a code's text through code_of.
inline constexpr geo::CertificateReason kAllReasons[] = {
    geo::CertificateReason::none,
    geo::CertificateReason::not_decided,
    geo::CertificateReason::certificate_switched_off,
    geo::CertificateReason::plane_filter_undecided,
    geo::CertificateReason::plane_filter_undecided_exact_fallback_off,
    geo::CertificateReason::plane_results_not_representable,
    geo::CertificateReason::subdivision_budget_exhausted,
    geo::CertificateReason::more_than_four_roots,
    geo::CertificateReason::interval_proof_failed_near_multiple_root,
    geo::CertificateReason::coefficient_overflow,
    geo::CertificateReason::cylinder_points_not_representable,
    geo::CertificateReason::exact_root_isolation_budget_exhausted,
    geo::CertificateReason::exact_coefficients_too_large,
    geo::CertificateReason::exact_intermediate_beyond_double_range,
    geo::CertificateReason::contact_not_representable_in_world,
    geo::CertificateReason::axes_parallel_within_tolerance,
    geo::CertificateReason::beyond_model_undecided,
};

/// The sentence of each C reason code (the C++ to_string, a NUL-terminated literal), looked up
/// once when the library loads: asking the kernel library for it on every certificate was an
/// out-of-line call across libraries, ~2 ns of a free-flight cj_detect.
extern const char* const* const kReasonTexts;

inline cj_certificate certificate_of(const geo::Certificate& c) {
  const int32_t reason = code_of(c.reason);
  return {code_of(c.level), reason, kReasonTexts[reason]};
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

}  // namespace clearjoint::c_api
