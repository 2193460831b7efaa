// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Error bounds of a contact's points and depth (Contact::p_WCj_error, p_WCi_error, depth_error):
// how far the double evaluation of eqs. (6)-(23) can lie from the same formulas evaluated in
// real arithmetic on the joint as given (exact centres, exact crossings, exact axis directions).
//
// Each bound adds three kinds of terms:
//  - the errors of the inputs: a rim centre's rounding bound (rounded_point.hpp), the crossing
//    points' certified bounds (which include the centre's), and the direction error of a unit
//    axis computed in double (kUnitAxisError);
//  - their propagation, through the Lipschitz constants written beside each bound;
//  - the rounding of the evaluation itself, kEvaluationRounding times the magnitudes involved.
// A bound that cannot be shown small (an ill-conditioned direction) falls back to a trivial one
// or to kNoErrorBound; it is never a guess.

#include <cmath>

#include "arithmetic/error_bounded.hpp"
#include "clearjoint/geometry/model/rim_arc.hpp"
#include "clearjoint/geometry/arithmetic/vector3.hpp"

namespace clearjoint::geometry::detail {

/// unit_axis() computes a / sqrt(a . a) in double (or Eigen's stableNormalized out of its safe
/// range): a . a within gamma_3, the square root and the division one rounding each, so each
/// component within about 4 u of a/|a|, the vector within 4 u sqrt(3) < 8 u of it.
inline constexpr double kUnitAxisError = 8 * kUnitRoundoff;
/// The evaluations below chain at most ten roundings (a cross product of cross products, a norm,
/// a division, a scaling and a sum): gamma_10 < 11 u of the magnitudes involved; 16 u leaves room
/// for a miscount.
inline constexpr double kEvaluationRounding = 16 * kUnitRoundoff;
/// A computed Euclidean norm is within a few u of the exact norm of its (rounded) vector: divide
/// by it shrunk by this factor to keep a bound a bound.
inline constexpr double kNormShrink = 1 - 0x1p-48;

/// |x/|x| - y/|y|| <= 2 |x - y| / |x| for any y (the triangle inequality on
/// (x - y)/|x| + y (1/|x| - 1/|y|)). For the direction of `length` = |x| computed, with
/// `perturbation` a bound on |x - y|; NaN-free only for length > 0.
inline double direction_error(double perturbation, double length) {
  return 2 * perturbation / (length * kNormShrink);
}

/// The trivial bound on the distance from `point` to any point of the exact rim (centre within
/// `centre_error` of `centre`, radius `radius`): |p - X| <= |p - c| + |c - c*| + |c* - X|.
inline double any_rim_point_error(const Vector3& point, const Vector3& centre, double centre_error,
                                  double radius) {
  return ((point - centre).norm() * (1 + kEvaluationRounding) + centre_error + radius) * (1 + kEvaluationRounding);
}

/// The point c + r x/|x| on a rim (centre c within `centre_error` of the exact one, radius r),
/// where x approximates, within `perturbation`, a vector x* whose direction from the exact centre
/// gives the exact point: within centre_error + r * direction_error + the evaluation's rounding
/// of the exact one; `point` is the computed c + (r/|x|) x. When the perturbation is not below
/// half of |x| (the direction is not even known to point the same way), the trivial bound.
inline double rim_point_along_error(const Vector3& point, const Vector3& centre, double centre_error,
                                    double radius, double perturbation, double length) {
  if (!(perturbation < 0.5 * length)) return any_rim_point_error(point, centre, centre_error, radius);
  const double rounding = kEvaluationRounding * (centre.cwiseAbs().sum() + radius);
  return (centre_error + radius * direction_error(perturbation, length) + rounding) * (1 + kEvaluationRounding);
}

}  // namespace clearjoint::geometry::detail
