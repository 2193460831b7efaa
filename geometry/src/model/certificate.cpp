// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/certificate.hpp"

namespace clearjoint::geometry {

std::string_view to_string(Certainty level) noexcept {
  switch (level) {
    case Certainty::exact: return "exact";
    case Certainty::certified: return "certified";
    case Certainty::uncertain: return "uncertain";
  }
  return "unknown";
}

std::string_view to_string(CertificateReason reason) noexcept {
  using R = CertificateReason;
  switch (reason) {
    case R::none: return "";
    case R::not_decided: return "not decided (a default-constructed certificate)";
    case R::certificate_switched_off: return "certificate switched off";
    case R::plane_filter_undecided: return "floating-point filter could not decide (tangent or parallel)";
    case R::plane_filter_undecided_exact_fallback_off:
      return "floating-point filter could not decide and the exact fallback is off";
    case R::plane_results_not_representable:
      return "crossing points, depth or their error bounds not representable in double (intermediate "
             "under- or overflow: input magnitudes too far apart); the topology is still decided";
    case R::subdivision_budget_exhausted: return "subdivision budget exhausted (roots too close: near tangency)";
    case R::more_than_four_roots: return "more than four roots found (cannot happen for a proper rim)";
    case R::interval_proof_failed_near_multiple_root: return "interval proof failed near a multiple root (tangency)";
    case R::coefficient_overflow: return "coefficient overflow in double precision";
    case R::cylinder_points_not_representable:
      return "crossing points or their error bounds not representable in double (intermediate under- or "
             "overflow: input magnitudes too far apart); the root count is still decided";
    case R::exact_root_isolation_budget_exhausted:
      return "exact tier gave up: root isolation exceeded its budget (input magnitudes too far apart)";
    case R::exact_coefficients_too_large:
      return "exact tier gave up: polynomial coefficients too large (input magnitudes too far apart)";
    case R::exact_intermediate_beyond_double_range:
      return "exact tier gave up: an intermediate value left the double range (input magnitudes too far apart)";
    case R::contact_not_representable_in_world:
      return "a contact point, depth or error bound not representable in double (coordinates too "
             "large for the joint's size); the contact's existence is still decided";
    case R::axes_parallel_within_tolerance:
      return "axes treated as parallel within DetectionOptions::parallel_angle_tolerance (eq. 5 relaxed; "
             "decided in double precision)";
    case R::beyond_model_undecided:
      return "a contact's depth lies within its error bound of the clearance: whether the joint is beyond "
             "the model (scenario beyond_model) is not proved; the contacts themselves are";
  }
  return "unknown";
}

std::string_view Certificate::reason_text() const noexcept { return to_string(reason); }

}  // namespace clearjoint::geometry
