// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The quantities that decide a rim against a plane (docs/circle-plane.md; paper eqs. 11-15), each
// with a rigorous error bound, and the cheap "which side is the whole rim on" test built on them.
// With s = n_p . (c - p) and w = n_p x n_c, the signed distance of rim point x(theta) from the
// plane is, times |n_p|, s + r |w| / |n_c| cos(theta - theta_m); the rim stays strictly on one
// side iff s^2 |n_c|^2 - r^2 |w|^2 > 0, the side of s.

#include <cmath>

#include "arithmetic/error_bounded.hpp"
#include "clearjoint/geometry/model/primitives.hpp"
#include "predicates/plane_terms.hpp"

namespace clearjoint::geometry::detail {

/// The terms of plane_terms.hpp, each with its error bound.
using PlaneQuantities = PlaneTerms<Bounded>;

/// Whether the a priori bounds of a_priori_bounds.hpp hold for these inputs (magnitudes).
bool plane_a_priori_bounds_apply(const Circle3& circle, const Plane3& plane);
/// Plain double with a priori bounds; only when plane_a_priori_bounds_apply.
PlaneQuantities plane_quantities_a_priori(const Circle3& circle, const Plane3& plane);
/// For inputs that need neither validation nor rescaling (scale_normalisation.hpp) and satisfy
/// plane_a_priori_bounds_apply, {true, plane_quantities_a_priori}; {false, zero} otherwise. Ready means: finite (NaN and infinity fail every comparison here),
/// normals with squares >= 2^-200 (so non-zero), radius and the largest length within the
/// unscaled range [2^-60, 2^61). Without the normals' power-of-two rescaling every double step of
/// the query scales exactly with them inside these limits, so the answers are those of the
/// rescaled inputs up to the bounds' underflow allowance. One pass: the guard's absolute values
/// and squares of the normals are the a priori terms' too (as two out-of-line calls they were
/// computed twice).
struct ReadyPlaneQuantities {
  bool ready = false;
  PlaneQuantities q;  ///< zero when not ready
};
ReadyPlaneQuantities plane_quantities_if_ready(const Circle3& circle, const Plane3& plane);
/// Running error bounds (error_bounded.hpp): any finite input; overflow gives non-finite bounds.
PlaneQuantities plane_quantities_running_error(const Circle3& circle, const Plane3& plane);


/// The pieces of widen_side_quantities, for callers that widen several s with one normal:
/// |n_p| rounded up from the enclosure of |n_p|^2, the bound on how far s moves, and the widening
/// of s and the discriminant by that shift.
inline constexpr double kWideningRounding = 1 + 16 * kUnitRoundoff;  // a few operations, rounded up
inline double plane_normal_length_bound(const Bounded& np2) {
  return std::sqrt(std::fabs(np2.value) + np2.error) * kWideningRounding;
}
inline double side_shift(double normal_length_bound, double distance_error) {
  return normal_length_bound * distance_error * kWideningRounding + kUnderflowError;
}
/// B is Bounded for one s, or PairBounded for two side by side (the axial prefilters of
/// candidate_prefilter_lanes.hpp, one base plane per lane): lane by lane the same operations, so
/// each lane holds the bits of the call for its s alone.
template <class B>
inline void widen_side_quantities_by_shift(B& s, B& discriminant, const Bounded& nc2, decltype(B::value) shift) {
  // s moves by delta, |delta| <= shift. s^2 moves by 2 s delta + delta^2: within
  // [-2 |s| shift + shift^2, 2 |s| shift + shift^2] when |s| >= shift (centre shift^2,
  // half-width 2 |s| shift); otherwise within [-s^2, 2 |s| shift + shift^2], inside
  // shift^2 +- (2 |s| + shift) shift. Times |n_c|^2.
  using V = decltype(B::value);
  const V high_s = magnitude(s.value) + s.error;
  const double high_nc2 = std::fabs(nc2.value) + nc2.error;
  const V low_s = magnitude(s.value) - s.error;
  const V centre_shift = shift * shift;
  const V half_width = select(low_s >= shift, 2.0 * high_s * shift, (2.0 * high_s + shift) * shift);
  const V value = discriminant.value + centre_shift * nc2.value;
  const V added_error = (half_width * high_nc2 + centre_shift * nc2.error) * kWideningRounding +
                        kUnitRoundoff * magnitude(value) + 2 * kUnderflowError;
  s.error = (s.error + shift) * kWideningRounding;
  discriminant = B{value, (discriminant.error + added_error) * kWideningRounding};
}

/// Widens s and the discriminant so that they hold for every rim centre c' and plane point p'
/// with |c' - c| + |p' - p| <= distance_error (rounded_point.hpp): s moves by at most
/// |n_p| distance_error. Inline, with widen_for_point_error: out of line, the call cost ~10 of
/// its ~57 instructions in a detection's plane query (callgrind).
inline void widen_side_quantities(Bounded& s, Bounded& discriminant, const Bounded& np2, const Bounded& nc2,
                                  double distance_error) {
  if (distance_error == 0.0) return;
  widen_side_quantities_by_shift(s, discriminant, nc2, side_shift(plane_normal_length_bound(np2), distance_error));
}
/// The same on the quantities of q.
inline void widen_for_point_error(PlaneQuantities& q, double distance_error) {
  widen_side_quantities(q.s, q.discriminant, q.np2, q.nc2, distance_error);
}

/// Where the deepest rim point lies in the rim frame (primitives.hpp: u = n_c x e_k / |n_c x e_k|,
/// v = n_c / |n_c| x u, k = frame_axis_index(n_c)), as a vector (along_u, along_v) whose angle is
/// theta_m. The plane normal's projections on the exact u and v are
///   n_p . (n_c x e_k) = w_k   and   n_p . (n_c / |n_c| x u) = (w x n_c)_k / (|n_c| |n_c x e_k|),
/// so (|n_c| w_k, (w x n_c)_k) is that pair times |n_c| |n_c x e_k| > 0: the same angle, from the
/// quantities already computed and no frame vectors (whose rounding would turn it). Enclosures
/// from the bounds on w and |n_c|^2 in q (a priori or running).
struct DeepestDirection {
  Bounded along_u, along_v;
};
DeepestDirection deepest_direction(const Circle3& circle, const PlaneQuantities& q);

/// Where the whole rim lies, proved; `undecided` when it crosses or touches the plane or the
/// bounds cannot tell.
enum class RimSide {
  strictly_negative,  ///< every rim point strictly on the side away from the normal
  strictly_positive,  ///< every rim point strictly on the normal's side
  undecided,
};
RimSide rim_side_of_plane(const Circle3& circle, const Plane3& plane);
/// The same with the magnitude guard already evaluated (plane_a_priori_bounds_apply, or a
/// caller's guard over a superset of the same values), proved for every centre and plane point
/// within distance_error (together) of the stored ones (widen_for_point_error).
RimSide rim_side_of_plane(const Circle3& circle, const Plane3& plane, bool a_priori_bounds_apply,
                          double distance_error = 0.0);

}  // namespace clearjoint::geometry::detail
