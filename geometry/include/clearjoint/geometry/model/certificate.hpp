// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// How far a numeric answer can be trusted, and why it is not trusted more.

#include <array>
#include <cstdint>
#include <string_view>
#include <tuple>

#include "clearjoint/geometry/model/enum_table.hpp"
#include "clearjoint/geometry/model/field_lists.hpp"

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
  edge_sides_undecided,    ///< pin-in-hole: two edge normals at right angles within their bounds
};

template <>
struct EnumTable<Certainty> {
  static constexpr std::string_view type_name = "Certainty";
  static constexpr auto entries = std::to_array({
      named_entry(Certainty::exact, "exact", "decided with exact rational arithmetic"),
      named_entry(Certainty::certified, "certified", "proved in floating point with rigorous error bounds"),
      named_entry(Certainty::uncertain, "uncertain", "not proved; the certificate's reason says why"),
  });
};
static_assert(entries_in_code_order<Certainty>());

/// A reason's label is its sentence ("" for `none`), which the outputs write.
template <>
struct EnumTable<CertificateReason> {
  using R = CertificateReason;
  static constexpr std::string_view type_name = "CertificateReason";
  static constexpr auto entries = std::to_array({
      named_entry(R::none, "none",
                  ""),
      named_entry(R::not_decided, "not_decided",
                  "not decided (a default-constructed certificate)"),
      named_entry(R::certificate_switched_off, "certificate_switched_off",
                  "certificate switched off"),
      named_entry(R::plane_filter_undecided, "plane_filter_undecided",
                  "floating-point filter could not decide (tangent or parallel)"),
      named_entry(R::plane_filter_undecided_exact_fallback_off, "plane_filter_undecided_exact_fallback_off",
                  "floating-point filter could not decide and the exact fallback is off"),
      named_entry(R::plane_results_not_representable, "plane_results_not_representable",
                  "crossing points, depth or their error bounds not representable in double (intermediate "
                  "under- or overflow: input magnitudes too far apart); the topology is still decided"),
      named_entry(R::subdivision_budget_exhausted, "subdivision_budget_exhausted",
                  "subdivision budget exhausted (roots too close: near tangency)"),
      named_entry(R::more_than_four_roots, "more_than_four_roots",
                  "more than four roots found (cannot happen for a proper rim)"),
      named_entry(R::interval_proof_failed_near_multiple_root, "interval_proof_failed_near_multiple_root",
                  "interval proof failed near a multiple root (tangency)"),
      named_entry(R::coefficient_overflow, "coefficient_overflow",
                  "coefficient overflow in double precision"),
      named_entry(R::cylinder_points_not_representable, "cylinder_points_not_representable",
                  "crossing points or their error bounds not representable in double (intermediate under- or "
                  "overflow: input magnitudes too far apart); the root count is still decided"),
      named_entry(R::exact_root_isolation_budget_exhausted, "exact_root_isolation_budget_exhausted",
                  "exact tier gave up: root isolation exceeded its budget (input magnitudes too far apart)"),
      named_entry(R::exact_coefficients_too_large, "exact_coefficients_too_large",
                  "exact tier gave up: polynomial coefficients too large (input magnitudes too far apart)"),
      named_entry(R::exact_intermediate_beyond_double_range, "exact_intermediate_beyond_double_range",
                  "exact tier gave up: an intermediate value left the double range (input magnitudes too far apart)"),
      named_entry(R::contact_not_representable_in_world, "contact_not_representable_in_world",
                  "a contact point, depth or error bound not representable in double (coordinates too "
                  "large for the joint's size); the contact's existence is still decided"),
      named_entry(R::axes_parallel_within_tolerance, "axes_parallel_within_tolerance",
                  "axes treated as parallel within DetectionOptions::parallel_angle_tolerance (eq. 5 relaxed; "
                  "decided in double precision)"),
      named_entry(R::beyond_model_undecided, "beyond_model_undecided",
                  "a contact's depth lies within its error bound of the clearance: whether the joint is beyond "
                  "the model (scenario beyond_model) is not proved; the contacts themselves are"),
      named_entry(R::edge_sides_undecided, "edge_sides_undecided",
                  "the pin-in-hole joint's two edge contacts have normals at right angles within their error "
                  "bounds: whether they bear at opposite sides of the pin (both_edges_opposite) or on one "
                  "side (both_edges_same_side) is not proved; the contacts themselves are"),
  });
};
static_assert(entries_in_code_order<CertificateReason>());

/// A trust level and why it is not stronger. Default-constructed: `uncertain`, `not_decided`
/// (nothing has been proved about a certificate no query filled in).
struct Certificate {
  Certainty level = Certainty::uncertain;
  CertificateReason reason = CertificateReason::not_decided;

  /// to_string(reason).
  std::string_view reason_text() const noexcept;
};

/// Its field list (model/field_lists.hpp): a member added above needs its line here.
template <>
struct ResultFields<Certificate> {
  using C = Certificate;
  static constexpr std::string_view type_name = "Certificate";
  static constexpr std::tuple fields{
      fields::plain("level", &C::level),
      fields::plain("reason", &C::reason, "A CertificateReason to branch on; none for certified answers.")};
};
static_assert(detail::lists_every_member<Certificate>(), "a member of Certificate is missing from its field list");

/// The level's key: "exact", "certified", "uncertain".
std::string_view to_string(Certainty level) noexcept;
/// The reason as a sentence ("certificate switched off", ...), its label; empty for `none`. The
/// one to_string that gives a label rather than a key: the outputs write the sentence.
std::string_view to_string(CertificateReason reason) noexcept;

/// The weaker of two certificates (used to combine the parts of one answer). Inline: detection
/// combines three or four per call, and the out-of-line call cost more than the comparison.
constexpr Certificate weakest(const Certificate& a, const Certificate& b) noexcept {
  // The enum lists levels from strongest to weakest, so the larger value is the weaker one.
  return static_cast<int>(b.level) > static_cast<int>(a.level) ? b : a;
}

}  // namespace clearjoint::geometry
