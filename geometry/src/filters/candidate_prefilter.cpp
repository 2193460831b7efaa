// SPDX-License-Identifier: BSD-3-Clause
#include "filters/candidate_prefilter.hpp"

#include "arithmetic/a_priori_bounds.hpp"
#include "arithmetic/filtered_predicate.hpp"
#include "filters/candidate_prefilter_lanes.hpp"
#include "predicates/rim_distance_polynomial.hpp"
#include "predicates/rim_plane_quantities.hpp"

namespace clearjoint::geometry::detail {
namespace {

// Each a priori bound here carries kUnderflowAllowance (a_priori_bounds.hpp) in place of the
// guard's lower limit: a lower limit per value cost a sixth of free-flight detection.

/// The upper half of the magnitude guard of a_priori_bounds.hpp: every input, and so every
/// difference c - p, at most 2^100 in magnitude (componentwise, via the 1-norms: |x|_inf <=
/// |x|_1, and |c - p|_1 <= |c|_1 + |p|_1). The base points are -+ each other.
bool guard(const CandidatePrefilterInput& in) {
  constexpr double kHalfLargest = 0.5 * kLargestGuardedInput;
  const double base = in.base_points[0].cwiseAbs().sum() + in.base_points[1].cwiseAbs().sum();
  const double rims = in.rim_centres[0].cwiseAbs().sum() + in.rim_centres[1].cwiseAbs().sum();
  const double radial = in.radial_centres[0].cwiseAbs().sum() + in.radial_centres[1].cwiseAbs().sum();
  return base <= kHalfLargest && rims <= kHalfLargest && radial <= kLargestGuardedInput &&
         in.bearing_axis.cwiseAbs().sum() <= kLargestGuardedInput &&
         in.journal_axis.cwiseAbs().sum() <= kLargestGuardedInput && in.bearing_radius <= kLargestGuardedInput;
}

/// Outside the guard: the two tests one by one, with their running error bounds.
CandidatesClear prove_one_by_one(const CandidatePrefilterInput& in) {
  CandidatesClear out;
  const Cylinder3 wall{Vector3::Zero(), in.bearing_axis, in.bearing_radius};
  for (int k = 0; k < 2; ++k) {
    const Circle3 section{in.radial_centres[k], in.journal_axis, in.journal_radius};
    out.radial[k] = rim_reach(section, wall, false, in.radial_errors[k]) == RimReach::strictly_inside;
    const Circle3 rim{in.rim_centres[k], in.journal_axis, in.journal_radius};
    const Plane3 base{in.base_points[k], k == 0 ? in.bearing_axis : Vector3(-in.bearing_axis)};
    out.axial[k] = rim_side_of_plane(rim, base, false, in.rim_errors[k] + in.base_errors[k]) ==
                   RimSide::strictly_negative;
  }
  return out;
}

}  // namespace

CandidatesClear prove_candidates_clear(const CandidatePrefilterInput& in) {
  const Vector3& a = in.bearing_axis;
  const Vector3& n = in.journal_axis;
  return floating_point_filter(
      guard(in),
      [&] {
        return prove_candidates_clear_in_guard({lanes(in.radial_centres), lanes(in.radial_errors),
                                                lanes(in.rim_centres), lanes(in.rim_errors), lanes(in.base_points),
                                                lanes(in.base_errors), a, n, a.cross(n),
                                                abs_cross(a.cwiseAbs(), n.cwiseAbs()), in.bearing_radius,
                                                in.journal_radius});
      },
      [&] { return prove_one_by_one(in); });
}

}  // namespace clearjoint::geometry::detail
