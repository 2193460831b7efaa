#include "candidate_prefilter.hpp"

#include "a_priori_bounds.hpp"
#include "rim_distance_polynomial.hpp"
#include "rim_plane_quantities.hpp"

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
  if (!guard(in)) return prove_one_by_one(in);
  CandidatesClear out;
  const Vector3& a = in.bearing_axis;
  const Vector3& n = in.journal_axis;
  const Vector3 a_abs = a.cwiseAbs();
  const double axis_norm2 = a.squaredNorm();  // |a_i|^2, its own absolute-value twin
  const double R = in.bearing_radius, r = in.journal_radius;

  // Radial: rim_reach's a priori "strictly inside" test. The axis point is 0, so q = c exactly.
  for (int k = 0; k < 2; ++k) {
    const double e = in.radial_errors[k];
    if (!(R - r > e)) continue;
    const double gap = (R - r) - e, gap_abs = (R - r) + e;
    const double gap2 = gap * gap * axis_norm2;
    const Vector3& c = in.radial_centres[k];
    const double offset2 = c.cross(a).squaredNorm();
    const double offset2_abs = abs_cross(c.cwiseAbs(), a_abs).squaredNorm();
    out.radial[k] = gap2 - offset2 > kGamma64 * (gap_abs * gap_abs * axis_norm2 + offset2_abs) * kMagnitudeInflation +
                                         kUnderflowAllowance;
  }

  // Axial: rim_side_of_plane's a priori "strictly negative" test (a_priori_terms). Base plane X
  // has normal sigma a_i (sigma = +1 at A, -1 at B): its s is sigma (a_i . (c - p)) and its
  // w = sigma (a_i x a_j), each rounded exactly as with the normal sigma a_i (negation is exact and
  // commutes with rounding), so |w|^2 and the twins are shared by both bases.
  const Vector3 w = a.cross(n);
  const Vector3 w_abs = abs_cross(a_abs, n.cwiseAbs());
  const double w2 = w.squaredNorm(), w2_abs = w_abs.squaredNorm(), nc2 = n.squaredNorm();
  const double r2 = r * r;
  const double r2_w2 = r2 * w2, r2_w2_abs = r2 * w2_abs;
  const Bounded np2 = a_priori_with_underflow(axis_norm2, axis_norm2);
  const Bounded nc2_bounded = a_priori_with_underflow(nc2, nc2);
  const double normal_length = plane_normal_length_bound(np2);  // |n_p| = |a_i|, rounded up
  for (int k = 0; k < 2; ++k) {
    const Vector3 d = in.rim_centres[k] - in.base_points[k];
    const double s_value = k == 0 ? a.dot(d) : -a.dot(d);
    const double s_abs = a_abs.dot(d.cwiseAbs());
    Bounded s = a_priori_with_underflow(s_value, s_abs);
    Bounded discriminant =
        a_priori_with_underflow(s_value * s_value * nc2 - r2_w2, s_abs * s_abs * nc2 + r2_w2_abs);
    widen_side_quantities_by_shift(s, discriminant, nc2_bounded,
                                   side_shift(normal_length, in.rim_errors[k] + in.base_errors[k]));
    out.axial[k] = discriminant.sign() > 0 && s.sign() < 0;
  }
  return out;
}

}  // namespace clearjoint::geometry::detail
