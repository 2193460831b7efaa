// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The four reach prefilters of candidate_prefilter.hpp inside their magnitude guard, computed for
// bases A and B side by side: lane 0 holds base A's value, lane 1 base B's. Inline, so that
// detect_contacts' free-flight proof (which builds these lanes from the poses directly) and
// prove_candidates_clear share one copy of the arithmetic.
//
// Bit for bit: the radial tests are rim_reach_terms.hpp's a priori form and the axial tests take
// s and the discriminant from plane_terms.hpp, on ValueAndTwin<Pair> (twinned.hpp): each lane a
// value and its twin rounded exactly as the scalar instance rounds them (a Pair rounds each lane as
// the scalar operation would, pair_lanes.hpp). So each lane decides what rim_reach and rim_side_of_plane decide for that base
// (test: DecidesAsTheOneByOneTestsDo), at about half the instructions of two scalar passes.

#include <array>

#include "arithmetic/a_priori_bounds.hpp"
#include "arithmetic/error_bounded.hpp"
#include "arithmetic/lane_vector3.hpp"
#include "arithmetic/pair_lanes.hpp"
#include "arithmetic/twinned.hpp"
#include "filters/candidate_prefilter.hpp"
#include "predicates/plane_terms.hpp"
#include "predicates/rim_plane_quantities.hpp"
#include "predicates/rim_reach_terms.hpp"

namespace clearjoint::geometry::detail {

/// CandidatePrefilterInput in lanes, with a_i x a_j and its absolute-value twin
/// abs_cross(|a_i|, |a_j|) (which detect_contacts' parallelism filter computes too).
struct CandidateLanes {
  LaneVector3 radial_centres;
  Lanes radial_errors;
  LaneVector3 rim_centres;
  Lanes rim_errors;
  LaneVector3 base_points;
  Lanes base_errors;
  Vector3 bearing_axis;
  Vector3 journal_axis;
  Vector3 axes_cross;
  Vector3 axes_cross_abs;
  double bearing_radius = 0.0;
  double journal_radius = 0.0;
};

/// prove_candidates_clear for inputs inside its magnitude guard (candidate_prefilter.cpp). Always
/// inlined: GCC kept it out of line, and passing CandidateLanes through memory cost ~60 of the
/// ~820 instructions of a free-flight detection (callgrind).
[[gnu::always_inline]] inline CandidatesClear prove_candidates_clear_in_guard(const CandidateLanes& in) {
  using Twin = ValueAndTwin<double>;
  using LaneTwin = ValueAndTwin<Lanes>;
  const Vector3& a = in.bearing_axis;
  const Vector3& n = in.journal_axis;
  const Vector3Of<Twin> axis{Twin::of(a.x()), Twin::of(a.y()), Twin::of(a.z())};  // |a| beside a
  const double axis_norm2 = a.squaredNorm();  // |a_i|^2, its own absolute-value twin
  const double R = in.bearing_radius, r = in.journal_radius;

  // Radial: rim_reach's a priori "strictly inside" test (rim_reach_terms.hpp), the rim of lane k
  // against the wall. The axis point is 0, so q = c exactly. The gap as rim_distance_polynomial.cpp
  // forms it (R - r its own twin where the gap is proved positive); the guard tests only the
  // upper limit, hence the underflow allowance.
  const LaneVector3& c = in.radial_centres;
  const OffsetFromAxis<LaneTwin> offset =
      offset_from_axis(Vector3Of<LaneTwin>{LaneTwin::of(c.x), LaneTwin::of(c.y), LaneTwin::of(c.z)}, axis);
  const Twin radii_gap = Twin::nonnegative(R - r);
  const LaneTwin e = LaneTwin::nonnegative(in.radial_errors);
  const LaneFlags radial = (radii_gap.value > e.value) &
                           a_priori_proves_positive_with_underflow(
                               inside_margin(offset.perp2, Twin::nonnegative(axis_norm2), radii_gap - e));

  // Axial: rim_side_of_plane's a priori "strictly negative" test (plane_terms.hpp). Base plane X
  // has normal sigma a_i (sigma = +1 at A, -1 at B): its s is sigma (a_i . (c - p)) and its
  // w = sigma (a_i x a_j), each rounded exactly as with the normal sigma a_i (negation is exact and
  // commutes with rounding), so |w|^2 and the twins are shared by both bases.
  const Twin w2 = squared_length(Vector3Of<Twin>{{in.axes_cross.x(), in.axes_cross_abs.x()},
                                                 {in.axes_cross.y(), in.axes_cross_abs.y()},
                                                 {in.axes_cross.z(), in.axes_cross_abs.z()}});
  const double nc2 = squared_length(Vector3Of<double>{n.x(), n.y(), n.z()});  // its own twin
  const Bounded np2 = a_priori_with_underflow(axis_norm2, axis_norm2);
  const Bounded nc2_bounded = a_priori_with_underflow(nc2, nc2);
  const double normal_length = plane_normal_length_bound(np2);  // |n_p| = |a_i|, rounded up
  const LaneVector3 d = in.rim_centres - in.base_points;
  LaneTwin s_terms = plane_offset(axis, Vector3Of<LaneTwin>{LaneTwin::of(d.x), LaneTwin::of(d.y), LaneTwin::of(d.z)});
  s_terms.value = s_terms.value * Lanes{1.0, -1.0};  // times sigma: exact, as the negation
  const LaneTwin discriminant_terms =
      plane_discriminant(s_terms, Twin::nonnegative(nc2), Twin::nonnegative(r), w2);
  PairBounded s = a_priori_with_underflow(s_terms);
  PairBounded discriminant = a_priori_with_underflow(discriminant_terms);
  // side_shift(normal_length, rim error + base error), per lane.
  const Lanes shift = normal_length * (in.rim_errors + in.base_errors) * kWideningRounding + kUnderflowError;
  widen_side_quantities_by_shift(s, discriminant, nc2_bounded, shift);
  const LaneFlags no_crossing = discriminant.positive(), inside_base = s.negative();

  const LaneFlags axial = no_crossing & inside_base;
  CandidatesClear out;
  for (int k = 0; k < 2; ++k) {
    out.radial[k] = radial[k] != 0;
    out.axial[k] = axial[k] != 0;
  }
  return out;
}

}  // namespace clearjoint::geometry::detail
