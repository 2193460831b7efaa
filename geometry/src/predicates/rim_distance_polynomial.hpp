// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The rim's squared distance to the cylinder axis as a trigonometric polynomial of degree 2 in
// the rim angle (docs/circle-cylinder.md, section 1). Its roots are the crossings of eqs. (16)-(17).

#include <array>
#include <cmath>
#include <optional>
#include <type_traits>

#include "arithmetic/angle_grid.hpp"
#include "arithmetic/error_bounded.hpp"
#include "arithmetic/pair_lanes.hpp"
#include "clearjoint/geometry/model/primitives.hpp"
#include "predicates/rim_reach_terms.hpp"

namespace clearjoint::geometry::detail {

/// g(theta) = k0 + k1 cos(theta) + k2 sin(theta) + k3 cos(2 theta) + k4 sin(2 theta)
///          = dist(x(theta), axis)^2 - R^2   [m^2],
/// x(theta) the rim point of CircleFrame angle theta. g > 0: beyond the wall. Each coefficient
/// carries a rigorous bound on its distance to the exact coefficient of the stored primitives.
/// Largest offset from an AngleBase (angle_grid.hpp) for which the Taylor sine and cosine are
/// used: their truncation error is below (1/16)^9 / 9! ~ 4e-17 for the sine, smaller for the
/// cosine.
inline constexpr double kMaxAngleOffset = 1.0 / 16;

/// cos and sin of one angle (cos_sin_near), or of two in lanes for T = Pair.
template <class T>
struct CosSinOf {
  T cos, sin;
};
using CosSin = CosSinOf<double>;

template <class T>
struct ValueAndSlopeOf {
  T value;
  T slope;
  T cos, sin;  ///< of the angle evaluated at (approximate_near), see kAngleAdditionTrigError
  T curvature;  ///< g'', for tier 1's Halley steps (callers that do not read it let the compiler drop it)
};
using ValueAndSlope = ValueAndSlopeOf<double>;

/// value_near's result: Bounded for one offset, PairBounded (error_bounded.hpp) for two, whose
/// lane(i) is what value_near gives at offset i.
template <class T>
using BoundedOf = std::conditional_t<std::is_same_v<T, Pair>, PairBounded, Bounded>;

/// Bound on |computed - true| of the cos and sin that approximate_near and value_near form by
/// angle addition at base + offset (|offset| <= kMaxAngleOffset): see cos_sin_near below.
inline constexpr double kAngleAdditionUlps = 24;
inline constexpr double kAngleAdditionTrigError =
    kAngleAdditionUlps * kUnitRoundoff + 4.1e-17;  // + the sine's Taylor remainder (1/16)^9 / 9!

/// g and g' at one angle, enclosed.
struct BoundedValueAndSlope {
  Bounded value, slope;
};

struct RimDistancePolynomial {
  std::array<Bounded, 5> k;

  Bounded value(double theta) const;
  Bounded derivative(double theta) const;
  /// value(theta) and derivative(theta), bit for bit, from one sine and cosine (tier 2 needs
  /// both at every arc's middle).
  BoundedValueAndSlope value_and_derivative(double theta) const;
  /// g / g' at theta from one sine-cosine evaluation (the Newton step).
  double approximate_newton_step(double theta) const;
  /// g, g' near a base angle whose sine and cosine are known, at the real angle
  /// base + offset (|offset| <= kMaxAngleOffset): one table look-up (angle_grid.hpp) serves a
  /// whole Halley run and its proof. Inline (below): they are the inner loop of tier 1, called a
  /// dozen times per crossing rim, and a call cost a third of each. Templates: T = double, or
  /// Pair for two offsets at once (Base = AngleBase for one base, AngleBaseOf<Pair> for one per
  /// lane), each lane bit for bit the double call (pair_lanes.hpp).
  template <class Base, class T>
  BoundedOf<T> value_near(const Base& base, T offset) const;
  template <class Base, class T>
  ValueAndSlopeOf<T> approximate_near(const Base& base, T offset) const;
  /// g, g' (plain double) from a cosine and sine of the angle.
  template <class T>
  ValueAndSlopeOf<T> approximate_at(CosSinOf<T> t) const;
  /// The coefficients' values, without their error bounds.
  std::array<double, 5> values() const { return {k[0].value, k[1].value, k[2].value, k[3].value, k[4].value}; }
  /// Sum of the coefficient error bounds: a bound on the coefficient part of g's error.
  double coefficient_error() const {
    return k[0].error + k[1].error + k[2].error + k[3].error + k[4].error;
  }

  /// Bound on |g''| over all angles: hypot(k1, k2) + 4 hypot(k3, k4) with coefficient errors.
  double second_derivative_bound() const;
  /// A looser bound on |g''| without second_derivative_bound's two libm hypot calls:
  /// |k1| + |k2| + 4 (|k3| + |k4|) with coefficient errors (at most sqrt(2) times wider). For tier
  /// 1's proofs (certified_rim_roots.cpp), where it is only weighed against |g'|.
  double curvature_bound() const;

  /// Bounds on |computed - true| of approximate_near's value and slope at the real angle
  /// base + offset, the same for every offset in the angle addition's range (below).
  struct NearErrorBounds {
    double value, slope;
  };
  NearErrorBounds near_error_bounds() const;

 private:
  /// value_near's bound on |computed - true| of g, for cosines and sines each within
  /// `trig_error` of the true ones (see value_near): one formula for value_near and
  /// near_error_bounds, per offset and at the largest offset.
  template <class T>
  T value_error_bound(T trig_error) const;
};

/// Taylor polynomials of sin (degree 7) and cos (degree 8) at 0, for |x| <= kMaxAngleOffset, in
/// Estrin's form (terms paired, the pairs combined by x^4):
///   cos = (1 - x^2/2) + x^4 ((1/24 - x^2/720) + x^4/40320),
///   sin = x ((1 - x^2/6) + x^4 (1/120 - x^2/5040)).
/// Error: Lagrange remainders |x|^9/9! and |x|^10/10!, plus rounding. In the cosine, 1 - x^2/2
/// is off by u (1 + x^2/2) (x^2 rounded, halving exact, the difference rounded), the x^4 term
/// (below x^4/24 < 7e-7) by a few u of itself, and the final sum by u: under 2.01u. In the sine,
/// the bracket is off by u (1 + x^2/2) + u and the product by u of it: under 3.01u |x| (the
/// rounded constants 1/6, 1/120, ..., 1/40320 add < u x^2). 4u covers both. Estrin's form, not
/// Horner's (2u and 3u |x|): this heads every Halley step's chain (certified_rim_roots.hpp), and
/// after x^2 its longest chain is x^4 and three dependent multiply-adds where Horner's was four
/// (a shorter chain; the accuracy suite's family figures unchanged). The innermost terms multiply by the rounded reciprocals instead
/// of dividing by 5040 and 40320: one rounding more (the constant's), of a term below
/// x^6 / 5040 < 2^-36, so far below the 4u; and the divisions were the longest latencies on the
/// iteration step's chain.
/// The reciprocals are constant expressions, folded at compile time whatever the flags of the
/// file that includes this header: under -frounding-math (which CGAL::CGAL asks for, and which
/// geometry/CMakeLists.txt keeps for the exact tiers only) GCC leaves an inexact 1.0 / 6 in
/// ordinary code as a run-time division. Either way each is 1/n rounded to nearest, the mode the
/// kernel runs in (error_bounded.hpp); folded, they cost no division per call.
inline constexpr double kInverse6 = 1.0 / 6, kInverse24 = 1.0 / 24, kInverse120 = 1.0 / 120,
                        kInverse720 = 1.0 / 720, kInverse5040 = 1.0 / 5040,
                        kInverse40320 = 1.0 / 40320, kInverse362880 = 1.0 / 362880;
template <class T>
struct SmallAngleTrig {
  T sin, cos;
};
template <class T>
SmallAngleTrig<T> small_angle_trig(T x) {
  const T x2 = x * x, x4 = x2 * x2;
  return {x * ((1 - x2 * kInverse6) + x4 * (kInverse120 - x2 * kInverse5040)),
          (1 - x2 * 0.5) + x4 * ((kInverse24 - x2 * kInverse720) + x4 * kInverse40320)};
}

/// cos and sin at base + offset by angle addition: the ones approximate_near and value_near use.
/// Bound on |computed - true| (kAngleAdditionUlps): the base's sine and cosine (kAngleGrid's
/// correctly rounded values, within u each; the budget still allows libm's 4u each,
/// error_bounded.hpp), the Taylor polynomials' rounding (4u, small_angle_trig) and the two
/// products and one sum of the addition (3u each of terms at most 1 + 1/16) add to under 12u; 24u
/// doubles that, and the slack also holds the cosine's Lagrange remainder (|x|^10 / 10! < 3e-19).
/// The sine's remainder (|x|^9 / 9! <= (1/16)^9 / 9! < 4.1e-17) is added separately.
template <class Base, class T>
CosSinOf<T> cos_sin_near(const Base& base, T offset) {
  static_assert(kMaxAngleOffset == 1.0 / 16);
  const SmallAngleTrig<T> small = small_angle_trig(offset);
  const auto bc = base.cos, bs = base.sin;
  return {bc * small.cos - bs * small.sin, bs * small.cos + bc * small.sin};
}

template <class Base, class T>
BoundedOf<T> RimDistancePolynomial::value_near(const Base& base, T offset) const {
  // Plain double evaluation with an a priori bound instead of the running error of `value`:
  // this is the proof step of every tier-1 root, so it should cost what approximate_near does.
  // With e_t the error of the computed c, s (kAngleAdditionUlps u plus the Taylor remainder),
  // cos2 = (c - s)(c + s) and sin2 = 2 s c are off by at most 2 (|c| + |s|) e_t + e_t^2 plus 3u
  // of rounding, under 4 e_t + 4u since |c| + |s| <= 1.5 here; the sum k0 + k1 c + ... is off by
  // sum |k_i| e_i (each true trig value is at most 1 in magnitude), the coefficients' own
  // errors, and its rounding, gamma_6 of sum |k_i| |t_i| <= 8u sum |k_i| (|t_i| <= 1 + e_t).
  // Each operation may also underflow (2^-1074 each, 32 of them cover the 25 here).
  const T value = approximate_near(base, offset).value;  // its slope is never formed (inline)

  const T a = magnitude(offset), a3 = a * a * a;
  // The sine's Taylor remainder a^9 / 9!, rounded to nearest (a few u of a term below 0.4 u:
  // inside the factor-2 slack of kAngleAdditionUlps).
  const T trig_error = kAngleAdditionUlps * kUnitRoundoff + a3 * a3 * a3 * kInverse362880;
  return {value, value_error_bound(trig_error)};
}

template <class T>
[[gnu::always_inline]] inline T RimDistancePolynomial::value_error_bound(T trig_error) const {
  const T double_angle_error = 4 * trig_error + 4 * kUnitRoundoff;
  const double first = std::fabs(k[1].value) + std::fabs(k[2].value);
  const double second = std::fabs(k[3].value) + std::fabs(k[4].value);
  const T error = coefficient_error() + first * trig_error + second * double_angle_error +
                  8 * kUnitRoundoff * (std::fabs(k[0].value) + first + second) + 32 * kUnderflowError;
  return error * kErrorInflation;
}

/// value_near's bound with the sine's Taylor remainder at its largest (kAngleAdditionTrigError:
/// |offset| = kMaxAngleOffset), so the same for every offset: tier 1's proof then forms it once
/// per rim, not per evaluation. The slope k2 c - k1 s + 2 (k4 cos2 - k3 sin2) (approximate_at)
/// is bounded as the value is: the coefficients' own errors (each true trig value is at most 1
/// in magnitude), |k1| + |k2| times the trig error and 2 (|k3| + |k4|) times the double-angle
/// error, and the rounding of the expression, gamma_3 of its terms' magnitudes, under
/// 8u (|k1| + |k2| + 2 (|k3| + |k4|)), plus underflow. test_rim_distance_polynomial.cpp checks
/// both against MPFR across the offset range. Always inlined (as value_error_bound): with the
/// shared helper GCC emitted it out of line, a call through the PLT on tier 1's path.
[[gnu::always_inline]] inline RimDistancePolynomial::NearErrorBounds RimDistancePolynomial::near_error_bounds() const {
  constexpr double trig_error = kAngleAdditionTrigError;
  constexpr double double_angle_error = 4 * trig_error + 4 * kUnitRoundoff;
  const double first = std::fabs(k[1].value) + std::fabs(k[2].value);
  const double second = std::fabs(k[3].value) + std::fabs(k[4].value);
  const double slope = (k[1].error + k[2].error) + 2 * (k[3].error + k[4].error) + first * trig_error +
                       2 * second * double_angle_error + 8 * kUnitRoundoff * (first + 2 * second) +
                       32 * kUnderflowError;
  return {value_error_bound(trig_error), slope * kErrorInflation};
}

inline double RimDistancePolynomial::curvature_bound() const {
  // g'' = -(k1 cos + k2 sin) - 4 (k3 cos2 + k4 sin2): sums of non-negative terms, each rounding
  // relative; (1 + 8u) covers the few of them.
  const double first = (std::fabs(k[1].value) + k[1].error) + (std::fabs(k[2].value) + k[2].error);
  const double second = (std::fabs(k[3].value) + k[3].error) + (std::fabs(k[4].value) + k[4].error);
  return (first + 4 * second) * (1 + 8 * kUnitRoundoff) + kUnderflowError;
}

template <class Base, class T>
ValueAndSlopeOf<T> RimDistancePolynomial::approximate_near(const Base& base, T offset) const {
  return approximate_at(cos_sin_near(base, offset));
}

/// g, g', g'' (plain double) from coefficient values k (RimDistancePolynomial::values(), or each
/// broadcast to both lanes of a Pair, as tier 1's Halley lanes hold them: once per rim instead
/// of at every use) and a cosine and sine of the angle.
template <class C, class T>
ValueAndSlopeOf<T> approximate_at(const std::array<C, 5>& k, CosSinOf<T> t) {
  const T c = t.cos, s = t.sin;
  const T cos2 = (c - s) * (c + s), sin2 = 2 * s * c;
  const T value = k[0] + k[1] * c + k[2] * s + k[3] * cos2 + k[4] * sin2;
  const T slope = k[2] * c - k[1] * s + 2 * (k[4] * cos2 - k[3] * sin2);
  const T curvature = -(k[1] * c + k[2] * s) - 4 * (k[3] * cos2 + k[4] * sin2);
  return {value, slope, c, s, curvature};
}

template <class T>
ValueAndSlopeOf<T> RimDistancePolynomial::approximate_at(CosSinOf<T> t) const {
  return detail::approximate_at(values(), t);
}

/// The rim centre's offset from the axis in plain double, with the operations the reach test,
/// the a priori polynomial and the widening each need: a query forms it once (axis_offset) and
/// hands it to them and to the reach guard, rather than each forming its own (~110 instructions
/// per query, callgrind).
struct AxisOffset {
  Vector3 q;               ///< c - p, rounded
  Vector3 perp, perp_abs;  ///< A = q x d and its absolute-value twin abs_cross(|q|, |d|)
  double perp2, perp2_abs; ///< |A|^2 and the twin's squared norm
  double axis_norm2;       ///< D = |d|^2, its own twin
};
AxisOffset axis_offset(const Circle3& circle, const Cylinder3& cylinder);

/// The coefficients with a priori error bounds (Higham's gamma_k on the absolute-value
/// expression) in plain double when every input magnitude lies in [2^-100, 2^100]; otherwise
/// with the running error bound, which also handles underflow and overflow.
RimDistancePolynomial rim_distance_polynomial(const Circle3& circle, const Cylinder3& cylinder);
/// The same, with the magnitude guard already evaluated (cylinder_a_priori_bounds_apply): a
/// query asks it once for both rim_reach and the polynomial.
RimDistancePolynomial rim_distance_polynomial(const Circle3& circle, const Cylinder3& cylinder,
                                              bool a_priori_bounds_apply);
/// The same, also handing back frame_of(circle), bit for bit, when the a priori path ran: it
/// has the frame's norms at hand, and a crossing rim needs the frame for its points (a square
/// root, a division and the axis choice saved). `frame` is left empty on the running-error path.
RimDistancePolynomial rim_distance_polynomial(const Circle3& circle, const Cylinder3& cylinder,
                                              bool a_priori_bounds_apply,
                                              std::optional<CircleFrame>& frame);
/// The same, given `offset` = axis_offset(circle, cylinder).
RimDistancePolynomial rim_distance_polynomial(const Circle3& circle, const Cylinder3& cylinder,
                                              const AxisOffset& offset, bool a_priori_bounds_apply,
                                              std::optional<CircleFrame>& frame);
/// Whether every input magnitude lies in [2^-100, 2^100] (or is zero): the a priori bounds of
/// a_priori_bounds.hpp hold.
bool cylinder_a_priori_bounds_apply(const Circle3& circle, const Cylinder3& cylinder);
/// The part of that guard rim_reach's a priori bound needs: q = c - p (rounded, as rim_reach
/// computes it), the axis and both radii in range. Checked first, the rest of the guard
/// (cylinder_a_priori_bounds_apply with reach_guard) only for the rims the reach test leaves
/// undecided: most rims stop at the reach test, and the guard was a quarter of their cost.
bool reach_a_priori_bounds_apply(const Circle3& circle, const Cylinder3& cylinder);
/// The same, with q taken from axis_offset(circle, cylinder).
bool reach_a_priori_bounds_apply(const AxisOffset& offset, const Circle3& circle,
                                 const Cylinder3& cylinder);
/// cylinder_a_priori_bounds_apply given reach_a_priori_bounds_apply's answer `reach_guard`.
bool cylinder_a_priori_bounds_apply(const Circle3& circle, const Cylinder3& cylinder,
                                    bool reach_guard);
/// The running-error version alone (the fallback, and a cross-check in the tests).
RimDistancePolynomial rim_distance_polynomial_running_error(const Circle3& circle,
                                                            const Cylinder3& cylinder);

/// Widens the coefficient bounds so that they also hold for every rim whose centre lies within
/// `centre_error` (Euclidean) of circle.center: only k0 = dist(c, axis)^2 - ... and the first
/// harmonic depend on the centre (docs/circle-cylinder.md, section 1). Every tier then proves
/// its answer for all those rims at once, the exact centre among them (rounded_point.hpp).
void widen_for_centre_error(RimDistancePolynomial& g, const Circle3& circle,
                            const Cylinder3& cylinder, double centre_error);
/// The same, given `offset` = axis_offset(circle, cylinder).
void widen_for_centre_error(RimDistancePolynomial& g, const Circle3& circle, const AxisOffset& offset,
                            double centre_error);

/// The reach test of rim_reach_terms.hpp, before any root finding.
/// Proved with the running error bound of error_bounded.hpp: the answer is never wrong.
RimReach rim_reach(const Circle3& circle, const Cylinder3& cylinder);
/// The same with the magnitude guard already evaluated, proved for every centre within
/// `centre_error` of circle.center (rounded_point.hpp).
RimReach rim_reach(const Circle3& circle, const Cylinder3& cylinder, bool a_priori_bounds_apply,
                   double centre_error = 0.0);
/// The same, given `offset` = axis_offset(circle, cylinder).
RimReach rim_reach(const Circle3& circle, const Cylinder3& cylinder, const AxisOffset& offset,
                   bool a_priori_bounds_apply, double centre_error);

}  // namespace clearjoint::geometry::detail
