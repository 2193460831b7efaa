// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A point that detection computes in double from exact inputs (a base or rim centre, eqs. 3-4,
// in the bearing-centred frame of detect_contacts), with a rigorous bound on its rounding and
// the recipe that rebuilds it exactly. The kernel's floating-point tiers widen their error
// bounds by `error`, so that every certified decision holds for the exact point; its exact tiers
// rebuild the exact point in rationals (exact_rational_point.hpp). Without this the certificates
// would be about the rounded centres only, and near a tangency the exact tier would decide, exactly,
// a joint that differs from the given one by an ulp (bench/detection measured such answers).

#include <cmath>

#include "arithmetic/error_bounded.hpp"
#include "clearjoint/geometry/arithmetic/vector3.hpp"

namespace clearjoint::geometry::detail {

/// exact = minuend - subtrahend + sign (length / 2) direction, all terms exact doubles and the
/// operations real ones; `value` its double evaluation and `error` >= |exact - value|
/// (Euclidean). sign is -1, 0 or +1.
struct RoundedPoint {
  Vector3 value = Vector3::Zero();
  double error = 0.0;
  Vector3 minuend = Vector3::Zero();
  Vector3 subtrahend = Vector3::Zero();
  Vector3 direction = Vector3::Zero();
  double length = 0.0;
  int sign = 0;
};

/// Evaluates the recipe as d = minuend - subtrahend, h = (length / 2) direction, value = d +- h,
/// each operation rounded once: |error of each| <= u |result| componentwise, plus 2^-1074 where a
/// product underflows (sums and differences that underflow are exact) and 2^-1075 |direction|
/// for the halving of a subnormal length. The Euclidean error is at most the sum of the
/// componentwise bounds (|x|_2 <= |x|_1): u (|d|_1 + |h|_1 + |value|_1), times (1 + 4u) for the
/// rounding of that sum, plus 8 * 2^-1074 for the underflow terms. Exact subtractions (Sterbenz:
/// the journal near the bearing far from the origin) still count u |d|; the bound stays relative
/// to the joint's size, not to the world coordinates.
/// The two bounds below, for callers that compute d, h and value themselves (detect_contacts,
/// which needs the recipes only for kernel queries): d = minuend - subtrahend alone, and
/// value = d +- h with h = (length / 2) direction.
inline double difference_rounding_bound(const Vector3& d) {
  return (kUnitRoundoff * d.cwiseAbs().sum()) * (1 + 4 * kUnitRoundoff);
}
/// offset_rounding_bound (below) from the 1-norms |d|_1 + |h|_1 (summed in that order) and
/// |value|_1: doubles, or Eigen lanes for the two rims at once (candidate_prefilter_lanes.hpp).
template <typename Norms>
Norms offset_rounding_bound_of_norms(const Norms& offset_norms, const Norms& value_norm) {
  return (kUnitRoundoff * (offset_norms + value_norm)) * (1 + 4 * kUnitRoundoff) + 8 * kUnderflowError;
}
inline double offset_rounding_bound(const Vector3& d, const Vector3& h, const Vector3& value) {
  return offset_rounding_bound_of_norms(d.cwiseAbs().sum() + h.cwiseAbs().sum(), value.cwiseAbs().sum());
}

inline RoundedPoint rounded_point(const Vector3& minuend, const Vector3& subtrahend, double length,
                                  int sign, const Vector3& direction) {
  RoundedPoint point;
  point.minuend = minuend;
  point.subtrahend = subtrahend;
  point.direction = direction;
  point.length = length;
  point.sign = sign;
  const Vector3 d = minuend - subtrahend;
  if (sign == 0) {
    point.value = d;
    point.error = difference_rounding_bound(d);
    return point;
  }
  const Vector3 h = (0.5 * length) * direction;
  point.value = sign > 0 ? Vector3(d + h) : Vector3(d - h);
  point.error = offset_rounding_bound(d, h, point.value);
  return point;
}

/// The bound after an exact scaling by 2^-e (scale_normalisation.hpp), kept a bound where it
/// would underflow.
inline double scaled_error(double error, int e) {
  if (error == 0.0 || e == 0) return error;
  const double scaled = std::ldexp(error, -e);
  return scaled > 0x1p-1022 ? scaled * (1 + 4 * kUnitRoundoff) : 0x1p-1022;
}

}  // namespace clearjoint::geometry::detail
