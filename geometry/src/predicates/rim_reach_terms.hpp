// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The reach test of a rim against a cylinder wall (docs/circle-cylinder.md, end of section 1),
// written once over the number type T. With q = c - p the rim centre from the axis point, d the
// axis, D = |d|^2 and A = q x d (the offset projected off the axis before squaring: no
// cancellation), dist(c, axis)^2 = |A|^2 / D. Every rim point lies within dist(c, axis) +- r of
// the axis, and dist(c, axis) moves by at most e when the centre moves by e (the rounding bound
// of rounded_point.hpp), so for every centre within e of c the whole rim is
//   strictly inside the wall  when gap = (R - r) - e > 0 and gap^2 D - |A|^2 > 0,
//   strictly outside the wall when |A|^2 - reach^2 D > 0, reach = (R + r) + e,
// and the crossings of eqs. (16)-(17) need no root finding.
// Instances in rim_distance_polynomial.cpp: Twinned for A and |A|^2 with their twins (axis_offset,
// which the polynomial and the widening share), ValueAndTwin<double> for the a priori margins and
// Bounded for the running-error filter; and ValueAndTwin<Pair>, two rims at once, for the radial
// prefilters of candidate_prefilter_lanes.hpp. The order of the operations is part of the definition: the
// floating-point instances' bits, and the a priori chains counted in rim_distance_polynomial.cpp,
// follow from it.

#include "arithmetic/vector3_of.hpp"

namespace clearjoint::geometry::detail {

/// Outcome of the reach test.
enum class RimReach {
  strictly_inside,   ///< dist(center, axis) + r < R: no rim point reaches the wall
  strictly_outside,  ///< dist(center, axis) - r > R: every rim point is beyond the wall
  undecided,
};

template <class T>
struct OffsetFromAxis {
  Vector3Of<T> perp;  ///< A = q x d
  T perp2;            ///< |A|^2
};

/// A and |A|^2 from q = c - p (formed by the caller: each number type has its own exact or
/// rounded difference, and the a priori chains count it as one rounding) and the axis d. The
/// axis may have a type of its own that T's operations take (ValueAndTwin<double> beside
/// ValueAndTwin<Pair>: one axis for both lanes).
template <class T, class Axis>
[[gnu::always_inline]] inline OffsetFromAxis<T> offset_from_axis(const Vector3Of<T>& q, const Vector3Of<Axis>& d) {
  const Vector3Of<T> perp{q.y * d.z - q.z * d.y, q.z * d.x - q.x * d.z, q.x * d.y - q.y * d.x};
  return {perp, perp.x * perp.x + perp.y * perp.y + perp.z * perp.z};
}

/// gap^2 D - |A|^2, positive (with gap) when the rim stays strictly inside. D of T's type or,
/// as the axis above, of a type T's operations take.
template <class T, class AxisNorm2>
[[gnu::always_inline]] inline T inside_margin(const T& perp2, const AxisNorm2& axis_norm2, const T& gap) {
  return gap * gap * axis_norm2 - perp2;
}

/// |A|^2 - reach^2 D, positive when the rim stays strictly outside.
template <class T, class AxisNorm2>
[[gnu::always_inline]] inline T outside_margin(const T& perp2, const AxisNorm2& axis_norm2, const T& reach) {
  return perp2 - reach * reach * axis_norm2;
}

/// The test on one rim: `radii_gap` R - r and `radii_sum` R + r as the number type forms them
/// (the a priori chains count each as one rounding), `centre_error` e. `gap_proved_positive(R - r,
/// e)` proves gap = (R - r) - e > 0 (from the inputs, so that the branch does not wait for the
/// gap) and `proved_positive` the sign of a margin, each the number type's own proof. Inline: the
/// a priori form is on the path most free-flight rims take.
template <class T, class AxisNorm2, class GapProvedPositive, class ProvedPositive>
[[gnu::always_inline]] inline RimReach rim_reach_of(const T& perp2, const AxisNorm2& axis_norm2, const T& radii_gap,
                                                    const T& radii_sum, const T& centre_error,
                                                    GapProvedPositive&& gap_proved_positive,
                                                    ProvedPositive&& proved_positive) {
  if (gap_proved_positive(radii_gap, centre_error) &&
      proved_positive(inside_margin(perp2, axis_norm2, radii_gap - centre_error))) {
    return RimReach::strictly_inside;
  }
  if (proved_positive(outside_margin(perp2, axis_norm2, radii_sum + centre_error))) return RimReach::strictly_outside;
  return RimReach::undecided;
}

}  // namespace clearjoint::geometry::detail
