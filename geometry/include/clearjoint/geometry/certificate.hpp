// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// How far a numeric answer can be trusted, and why it is not trusted more.

#include <cstdint>
#include <string_view>

namespace clearjoint::geometry {

/// Trust level of an answer, from strongest to weakest.
enum class Certainty : std::uint8_t {
  /// Decided with exact rational arithmetic on the stored doubles (CGAL); for detect_contacts,
  /// on the joint those doubles define (exact base centres, joint_geometry.hpp).
  exact,
  /// Proved with floating-point arithmetic and rigorous error bounds (interval or
  /// running-error analysis): the true answer lies in the reported enclosures.
  certified,
  /// Not proved; `Certificate::reason` says why.
  uncertain,
};

/// Why an answer is `uncertain`, or, for an `exact` one, why the floating-point tiers did not
/// decide it. `none` for `certified` answers. A caller can branch on it; to_string() gives the
/// sentence for humans.
enum class CertificateReason : std::uint8_t {
  none,                        ///< nothing to report (every `certified` answer)
  not_decided,                 ///< a default-constructed Certificate: no query filled it
  certificate_switched_off,    ///< IntersectionOptions::certify is false
  // Circle-plane topology (eqs. 11-15):
  plane_filter_undecided,      ///< the filter could not decide: tangent or parallel (exact tier decided)
  plane_filter_undecided_exact_fallback_off,  ///< the same, and the exact tier was switched off
  plane_results_not_representable,  ///< crossings, depth or bounds overflow or underflow double
  // Circle-cylinder roots (eqs. 16-21), floating-point tiers:
  subdivision_budget_exhausted,      ///< roots too close to separate: near a tangency
  more_than_four_roots,              ///< cannot happen for a proper rim
  interval_proof_failed_near_multiple_root,  ///< a tangency
  coefficient_overflow,              ///< the rim polynomial's coefficients overflow double
  cylinder_points_not_representable, ///< crossing points or bounds overflow or underflow double
  // Circle-cylinder roots, exact tier giving up (input magnitudes too far apart):
  exact_root_isolation_budget_exhausted,
  exact_coefficients_too_large,
  exact_intermediate_beyond_double_range,
  // Detection (eqs. 5-23):
  contact_not_representable_in_world,  ///< a contact's point, depth or bound has no finite double bound
  axes_parallel_within_tolerance,      ///< DetectionOptions::parallel_angle_tolerance relaxed eq. (5)
  beyond_model_undecided,  ///< a depth within its error bound of the clearance: beyond the model or not
};

/// A trust level and why it is not stronger. Default-constructed: `uncertain`, `not_decided`
/// (nothing has been proved about a certificate no query filled in).
struct Certificate {
  Certainty level = Certainty::uncertain;
  CertificateReason reason = CertificateReason::not_decided;

  /// to_string(reason).
  std::string_view reason_text() const noexcept;
};

std::string_view to_string(Certainty level) noexcept;
/// The reason as a sentence ("certificate switched off", ...); empty for `none`.
std::string_view to_string(CertificateReason reason) noexcept;

/// The weaker of two certificates (used to combine the parts of one answer). Inline: detection
/// combines three or four per call, and the out-of-line call cost more than the comparison.
constexpr Certificate weakest(const Certificate& a, const Certificate& b) noexcept {
  // The enum lists levels from strongest to weakest, so the larger value is the weaker one.
  return static_cast<int>(b.level) > static_cast<int>(a.level) ? b : a;
}

}  // namespace clearjoint::geometry
