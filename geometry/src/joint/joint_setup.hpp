// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What detect_contacts computes from the inputs before any candidate contact is tested: eq. (5)
// decided exactly, the joint in the bearing-centred frame (set_up, eqs. 1-4), and the fast path
// that proves free flight straight from the poses (prefilter_if_ready) and hands set_up's values
// on when it cannot. The two paths must give the same values bit for bit; a test compares them
// field by field over generated poses (tests/geometry/joint/test_joint_setup.cpp).
//
// The functions are in an unnamed namespace: detect_contacts.cpp is their one user in the
// library, and GCC inlines a function called once only where no other translation unit can see
// it (the code of detect_contacts depends on it). The test includes them too.

#include <array>
#include <cmath>

#include "arithmetic/a_priori_bounds.hpp"
#include "arithmetic/error_bounded.hpp"
#include "arithmetic/rounded_point.hpp"
#include "arithmetic/scale_normalisation.hpp"
#include "arithmetic/unit_axis_range.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "exact/parallel_axes_exact.hpp"
#include "filters/candidate_prefilter.hpp"
#include "filters/candidate_prefilter_lanes.hpp"

namespace clearjoint::geometry::detail {

/// Everything the candidate contacts need, computed once.
struct JointSetup {
  double bearing_radius = 0.0;
  double journal_radius = 0.0;
  double radial_clearance = 0.0;  // eq. (1)
  double axial_clearance = 0.0;   // eq. (2)
  double bearing_length = 0.0;
  double journal_length = 0.0;
  Vector3 p_WPi = Vector3::Zero();
  Vector3 p_WPj = Vector3::Zero();
  Vector3 bearing_axis_hat_W = Vector3::UnitZ();
  Vector3 journal_axis_hat_W = Vector3::UnitZ();
  Vector3 bearing_axis_W = Vector3::UnitZ();  // as given, for the kernel primitives
  Vector3 journal_axis_W = Vector3::UnitZ();
  // The same scaled by powers of two as each circle-cylinder query scales them
  // (scale_normalisation.hpp), once per joint instead of once per query.
  Vector3 bearing_axis_scaled_W = Vector3::UnitZ();
  Vector3 journal_axis_scaled_W = Vector3::UnitZ();
  // Every input passed prefilter_if_ready's tests (valid, inside the magnitude guard, so every
  // centre is finite): the kernel queries need not check their primitives again.
  bool inputs_in_guard = false;
  // The centres rounded to double, each with a bound on its rounding (rounded_point.hpp); their
  // exact recipes are built only for the kernel queries (rounded_centre). Index 0: base A, 1: B.
  std::array<Vector3, 2> bearing_bases;  // eqs. (3)-(4)
  std::array<double, 2> bearing_base_errors{};
  std::array<Vector3, 2> journal_rims;   // centres of the journal rims facing A and B
  std::array<double, 2> journal_rim_errors{};
  double journal_centre_error = 0.0;     // of p_WPj (P_j - P_i, rounded)
  int toward_a = 1;                      // +1: the journal's base A faces bearing base A
  Vector3 p_WPi_world = Vector3::Zero();  // the recipes' inputs
  Vector3 p_WPj_world = Vector3::Zero();
};

/// What prefilter_if_ready found: when `ready`, whether eq. (5) holds exactly and the
/// prefilters' answer, as detect_aligned or detect_misaligned would compute them.
struct Prefilter {
  bool ready = false;
  bool exactly_parallel = false;
  CandidatesClear clear;
  bool no_contact = false;  ///< every candidate clear: the whole answer
  // Ready and not no_contact: set_up's values (the same operations), the unit axes, h_i,
  // P_j - P_i, the rims in lanes with their errors, the bases' error. Left unset otherwise (no
  // initialisers: writing them cost ~17 instructions per free flight).
  Vector3 bearing_axis_hat;
  Vector3 journal_axis_hat;
  Vector3 h_i;
  Vector3 p_WPj;
  LaneVector3 rims;
  Lanes rim_errors;
  double base_error;
  int toward_a;
};

namespace {

/// a*b == c*d in real arithmetic: Dekker's two-product in range, rationals otherwise.
bool products_equal(double a, double b, double c, double d) {
  if (in_two_product_range(a) && in_two_product_range(b) && in_two_product_range(c) &&
      in_two_product_range(d)) {
    return exactly_equal_products(a, b, c, d);
  }
  return exact_products_equal(a, b, c, d);
}

/// The floating-point filter of eq. (5): a component of the cross product computed in double is
/// a difference of two rounded products, within gamma_64 of its absolute-value twin plus the
/// products' underflow (a_priori_bounds.hpp) of the exact one; beyond that it is not zero. True
/// when `cross` = a x b (rounded) has such a component, `twin` = abs_cross(|a|, |b|).
bool cross_proved_nonzero(const Vector3& cross, const Vector3& twin) {
  constexpr double kProductUnderflow = 4 * kUnderflowError;
  for (int i = 0; i < 3; ++i) {
    if (std::fabs(cross[i]) > kGamma64 * twin[i] * kMagnitudeInflation + kProductUnderflow) {
      return true;
    }
  }
  return false;
}

/// eq. (5): a_i x a_j = 0, decided exactly on the stored doubles. First the filter (every
/// misaligned pose stops there: the axes are not parallel), otherwise the exact test of each
/// component.
bool cross_exactly_zero(const Vector3& a, const Vector3& b) {
  return products_equal(a.y(), b.z(), a.z(), b.y()) && products_equal(a.z(), b.x(), a.x(), b.z()) &&
         products_equal(a.x(), b.y(), a.y(), b.x());
}
bool axes_exactly_parallel(const Vector3& a, const Vector3& b) {
  if (cross_proved_nonzero(a.cross(b), abs_cross(a.cwiseAbs(), b.cwiseAbs()))) return false;
  return cross_exactly_zero(a, b);
}


/// The fields of JointSetup that both set_up overloads take from the inputs unchanged.
/// Inlined into both, so that the default values of the fields they set next are not stored
/// first (GCC kept it out of line).
[[gnu::always_inline]] inline JointSetup inputs_as_given(const JointDimensions& dimensions,
                                                         const PartPose& bearing_in_world,
                                                         const PartPose& journal_in_world) {
  JointSetup s;
  s.bearing_radius = dimensions.bearing_radius;
  s.journal_radius = dimensions.journal_radius;
  s.radial_clearance = dimensions.radial_clearance();
  s.axial_clearance = dimensions.axial_clearance();
  s.bearing_length = dimensions.bearing_length;
  s.journal_length = dimensions.journal_length;
  s.p_WPi_world = bearing_in_world.p_WP;
  s.p_WPj_world = journal_in_world.p_WP;
  s.bearing_axis_W = bearing_in_world.axis_W;
  s.journal_axis_W = journal_in_world.axis_W;
  s.bearing_axis_scaled_W = direction_scaled(s.bearing_axis_W);
  s.journal_axis_scaled_W = direction_scaled(s.journal_axis_W);
  return s;
}

/// Everything is computed in a frame translated to the bearing centre P_i: the rounding of the
/// base and rim centres (eqs. 3-4) is then relative to the joint's size, not to how far the
/// joint sits from the world origin (at 1e13 m from it an ulp is larger than the clearance).
/// The contact points are translated back at the end. The centres are exactly
/// P_j - P_i +- (L/2) a_hat (a_hat = unit_axis, the joint's definition in joint_geometry.hpp);
/// their roundings are carried into the kernel's bounds and exact tiers. The values and bounds
/// are those of rounded_point (the same operations), without building its recipes: in
/// free flight no recipe is ever needed.
JointSetup set_up(const JointDimensions& dimensions, const PartPose& bearing_in_world,
                  const PartPose& journal_in_world) {
  JointSetup s = inputs_as_given(dimensions, bearing_in_world, journal_in_world);
  s.p_WPj = journal_in_world.p_WP - bearing_in_world.p_WP;
  s.bearing_axis_hat_W = unit_axis(bearing_in_world);
  s.journal_axis_hat_W = unit_axis(journal_in_world);
  // Labels follow the bearing: when a_j points against a_i, the journal's "B" base faces A.
  s.toward_a = s.bearing_axis_W.dot(s.journal_axis_W) >= 0.0 ? +1 : -1;
  const Vector3 h_i = (0.5 * dimensions.bearing_length) * s.bearing_axis_hat_W;
  const Vector3 h_j = (0.5 * dimensions.journal_length) * s.journal_axis_hat_W;
  s.bearing_bases = {h_i, -h_i};
  s.journal_rims = s.toward_a > 0 ? std::array<Vector3, 2>{s.p_WPj + h_j, s.p_WPj - h_j}
                                  : std::array<Vector3, 2>{s.p_WPj - h_j, s.p_WPj + h_j};
  // rounded_point's bounds (the base points are 0 - 0 +- h_i).
  s.journal_centre_error = difference_rounding_bound(s.p_WPj);
  const double base_error = offset_rounding_bound(Vector3::Zero(), h_i, h_i);
  s.bearing_base_errors = {base_error, base_error};
  for (int k = 0; k < 2; ++k) {
    s.journal_rim_errors[k] = offset_rounding_bound(s.p_WPj, h_j, s.journal_rims[k]);
  }
  return s;
}

/// The prefilters of a misaligned joint's four candidates on set_up's values (detect_misaligned):
/// the rims for the radial and the axial tests.
CandidatesClear prove_misaligned_candidates_clear(const JointSetup& s) {
  return prove_candidates_clear({s.journal_rims, s.journal_rim_errors, s.journal_rims, s.journal_rim_errors,
                                 s.bearing_bases, s.bearing_base_errors, s.bearing_axis_W, s.journal_axis_W,
                                 s.bearing_radius, s.journal_radius});
}
/// Those of an aligned joint (detect_aligned): the line's test on the journal's mid-length section
/// (its centre P_j - P_i, in both lanes), the faces' on the rims.
CandidatesClear prove_aligned_candidates_clear(const JointSetup& s) {
  return prove_candidates_clear({{s.p_WPj, s.p_WPj},
                                 {s.journal_centre_error, s.journal_centre_error},
                                 s.journal_rims, s.journal_rim_errors, s.bearing_bases, s.bearing_base_errors,
                                 s.bearing_axis_W, s.journal_axis_W, s.bearing_radius, s.journal_radius});
}

/// The prefilters of the four candidates (misaligned) or of the line and the two faces (aligned)
/// straight from the inputs, for inputs that need no validation, rescaling or angle test. Ready
/// when
///  - 0 < Rj < Ri and 0 < Lj < Li (their finiteness: below),
///  - the angle tolerance is +-0 (eq. 5 is then decided exactly, and no sine is needed),
///  - both axes have |a|^2 in unit_axis' direct range (so each is finite and non-zero, and its
///    unit axis is a / sqrt(|a|^2), computed here as unit_axis does),
///  - and the prefilters' magnitude guard holds (candidate_prefilter.cpp), which also makes Ri and
///    Li finite (Ri <= 2^100; an infinite or NaN Li makes |h_i|_1 infinite or NaN) and both
///    poses' centres (a non-finite component of P_i or P_j makes that component of P_j - P_i,
///    and so of a rim centre, infinite or NaN).
/// Then every validate() passes, and set_up would compute the very centres, errors and guard
/// values computed here (the same operations in the same order; the rims and bases as
/// P_j - P_i + (+-1) h and (+-1) h_i per lane, where adding -h is subtracting h, bit for bit;
/// |0|_1 + |h_i|_1 = |h_i|_1 exactly): `clear` is what detect_aligned's or detect_misaligned's
/// prove_candidates_clear would answer. test_joint_setup.cpp holds the two paths to that.
/// Always inlined into its one caller: GCC kept it out of line once detect_contacts grew, and
/// handing `found` back through memory cost ~20 instructions per free flight (callgrind).
[[gnu::always_inline]] inline void prefilter_if_ready(const JointDimensions& dimensions, const PartPose& bearing,
                                                      const PartPose& journal, const DetectionOptions& options,
                                                      Prefilter& found) {
  const double Ri = dimensions.bearing_radius, Rj = dimensions.journal_radius;
  const double Li = dimensions.bearing_length, Lj = dimensions.journal_length;
  const Vector3& a_i = bearing.axis_W;
  const Vector3& a_j = journal.axis_W;
  const double squared_i = a_i.squaredNorm(), squared_j = a_j.squaredNorm();
  if (!((Rj > 0.0) & (Rj < Ri) & (Lj > 0.0) & (Lj < Li) & (options.parallel_angle_tolerance == 0.0) &
        in_safe_square_range(squared_i) & in_safe_square_range(squared_j))) {
    return;
  }
  // eq. (5), as axes_exactly_parallel decides it; the cross product and its twin serve the axial
  // prefilters too.
  const Vector3 cross = a_i.cross(a_j);
  const Vector3 twin = abs_cross(a_i.cwiseAbs(), a_j.cwiseAbs());
  found.exactly_parallel = !cross_proved_nonzero(cross, twin) && cross_exactly_zero(a_i, a_j);
  const Vector3 a_i_hat = a_i / std::sqrt(squared_i), a_j_hat = a_j / std::sqrt(squared_j);
  const Vector3 h_i = (0.5 * Li) * a_i_hat;
  const Vector3 h_j = (0.5 * Lj) * a_j_hat;
  const Vector3 p_WPj = journal.p_WP - bearing.p_WP;
  const double toward_a = a_i.dot(a_j) >= 0.0 ? 1.0 : -1.0;
  const LaneVector3 rims = both_lanes(p_WPj) + scaled(Lanes{toward_a, -toward_a}, h_j);
  const Lanes rim_norms = one_norm(rims);
  const double h_i_norm = h_i.cwiseAbs().sum();
  const double p_WPj_norm = p_WPj.cwiseAbs().sum();
  constexpr double kHalfLargest = 0.5 * kLargestGuardedInput;
  // The guard's radial term: the rims when misaligned (already within the rims' half), the
  // journal centre twice when aligned.
  found.ready = (h_i_norm + h_i_norm <= kHalfLargest) & (rim_norms[0] + rim_norms[1] <= kHalfLargest) &
                (!found.exactly_parallel | (p_WPj_norm + p_WPj_norm <= kLargestGuardedInput)) &
                (a_i.cwiseAbs().sum() <= kLargestGuardedInput) &
                (a_j.cwiseAbs().sum() <= kLargestGuardedInput) & (Ri <= kLargestGuardedInput);
  if (!found.ready) return;
  const Lanes rim_errors =
      offset_rounding_bound_of_norms<Lanes>(broadcast(p_WPj_norm + h_j.cwiseAbs().sum()), rim_norms);
  const double base_error = offset_rounding_bound_of_norms(h_i_norm, h_i_norm);
  const LaneVector3 bases = scaled(Lanes{1.0, -1.0}, h_i);
  // Aligned, the line's test takes the journal's mid-length section (detect_aligned).
  const LaneVector3 radial_centres = found.exactly_parallel ? both_lanes(p_WPj) : rims;
  const Lanes radial_errors =
      found.exactly_parallel ? broadcast(difference_rounding_bound(p_WPj)) : rim_errors;
  found.clear = prove_candidates_clear_in_guard({radial_centres, radial_errors, rims, rim_errors, bases,
                                                         broadcast(base_error), a_i, a_j, cross, twin, Ri, Rj});
  const CandidatesClear& c = found.clear;
  // Aligned, the line is tested on the first lane (detect_aligned).
  // Bitwise, not &&: each flag depends on the pose, and a short-circuit chain mispredicted
  // ~0.7 times per detection (callgrind's branch simulator).
  found.no_contact = c.radial[0] & (found.exactly_parallel | c.radial[1]) & c.axial[0] & c.axial[1];
  if (found.no_contact) return;  // set_up's values are not needed
  found.bearing_axis_hat = a_i_hat;
  found.journal_axis_hat = a_j_hat;
  found.h_i = h_i;
  found.p_WPj = p_WPj;
  found.rims = rims;
  found.rim_errors = rim_errors;
  found.base_error = base_error;
  found.toward_a = toward_a > 0.0 ? +1 : -1;
  return;
}

/// set_up from the values prefilter_if_ready computed when `ready` is ready and found a
/// candidate not clear (the same values bit for bit: see there; the rims' lanes are (+-1) h_j
/// from P_j - P_i in set_up's order, lane 0 facing A).
JointSetup set_up(const JointDimensions& dimensions, const PartPose& bearing_in_world,
                  const PartPose& journal_in_world, const Prefilter& ready) {
  JointSetup s = inputs_as_given(dimensions, bearing_in_world, journal_in_world);
  s.p_WPj = ready.p_WPj;
  s.bearing_axis_hat_W = ready.bearing_axis_hat;
  s.journal_axis_hat_W = ready.journal_axis_hat;
  s.toward_a = ready.toward_a;
  s.bearing_bases = {ready.h_i, -ready.h_i};
  const LaneVector3& r = ready.rims;
  s.journal_rims = {Vector3(r.x[0], r.y[0], r.z[0]), Vector3(r.x[1], r.y[1], r.z[1])};
  s.journal_centre_error = difference_rounding_bound(s.p_WPj);
  s.bearing_base_errors = {ready.base_error, ready.base_error};
  s.journal_rim_errors = {ready.rim_errors[0], ready.rim_errors[1]};
  s.inputs_in_guard = true;
  return s;
}

}  // namespace

}  // namespace clearjoint::geometry::detail
