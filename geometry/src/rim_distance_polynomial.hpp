#pragma once
// The rim's squared distance to the cylinder axis as a trigonometric polynomial of degree 2 in
// the rim angle (docs/circle-cylinder.md, section 1). Its roots are the crossings of eqs. (16)-(17).

#include <array>

#include "clearjoint/geometry/primitives.hpp"
#include "error_bounded.hpp"

namespace clearjoint::geometry::detail {

/// g(theta) = k0 + k1 cos(theta) + k2 sin(theta) + k3 cos(2 theta) + k4 sin(2 theta)
///          = dist(x(theta), axis)^2 - R^2   [m^2],
/// x(theta) the rim point of CircleFrame angle theta. g > 0: beyond the wall. Each coefficient
/// carries a rigorous bound on its distance to the exact coefficient of the stored primitives.
/// Largest offset for which the Taylor sine and cosine of AngleBase are used: their truncation
/// error is below (1/16)^9 / 9! ~ 4e-17 for the sine, smaller for the cosine.
inline constexpr double kMaxAngleOffset = 1.0 / 16;

/// An angle with its sine and cosine from libm (2 ulps each, see error_bounded.hpp).
struct AngleBase {
  double angle;
  BoundedSinCos trig;
  explicit AngleBase(double theta) : angle(theta), trig(sincos_of(theta)) {}
};

struct ValueAndSlope {
  double value;
  double slope;
  double cos, sin;  ///< of the angle evaluated at (approximate_near), see kAngleAdditionTrigError
};

/// Bound on |computed - true| of the cos and sin that approximate_near and value_near form by
/// angle addition at base + offset (|offset| <= kMaxAngleOffset): see rim_distance_polynomial.cpp.
inline constexpr double kAngleAdditionUlps = 24;
inline constexpr double kAngleAdditionTrigError =
    kAngleAdditionUlps * kUnitRoundoff + 4.1e-17;  // + the sine's Taylor remainder (1/16)^9 / 9!

struct RimDistancePolynomial {
  std::array<Bounded, 5> k;

  Bounded value(double theta) const;
  Bounded derivative(double theta) const;
  /// g / g' at theta from one sine-cosine evaluation (the Newton step).
  double approximate_newton_step(double theta) const;
  /// g, g' near a base angle whose sine and cosine are known, at the real angle
  /// base + offset (|offset| <= kMaxAngleOffset): one libm call serves a whole Newton run and
  /// its proof. See AngleBase.
  Bounded value_near(const struct AngleBase& base, double offset) const;
  struct ValueAndSlope approximate_near(const struct AngleBase& base, double offset) const;
  /// Sum of the coefficient error bounds: a bound on the coefficient part of g's error.
  double coefficient_error() const {
    return k[0].error + k[1].error + k[2].error + k[3].error + k[4].error;
  }

  /// Bound on |g''| over all angles: hypot(k1, k2) + 4 hypot(k3, k4) with coefficient errors.
  double second_derivative_bound() const;
};

/// The coefficients with a priori error bounds (Higham's gamma_k on the absolute-value
/// expression) in plain double when every input magnitude lies in [2^-100, 2^100]; otherwise
/// with the running error bound, which also handles underflow and overflow.
RimDistancePolynomial rim_distance_polynomial(const Circle3& circle, const Cylinder3& cylinder);
/// The same, with the magnitude guard already evaluated (cylinder_a_priori_bounds_apply): a
/// query asks it once for both rim_reach and the polynomial.
RimDistancePolynomial rim_distance_polynomial(const Circle3& circle, const Cylinder3& cylinder,
                                              bool a_priori_bounds_apply);
/// Whether every input magnitude lies in [2^-100, 2^100] (or is zero): the a priori bounds of
/// a_priori_bounds.hpp hold.
bool cylinder_a_priori_bounds_apply(const Circle3& circle, const Cylinder3& cylinder);
/// The running-error version alone (the fallback, and a cross-check in the tests).
RimDistancePolynomial rim_distance_polynomial_running_error(const Circle3& circle,
                                                            const Cylinder3& cylinder);

/// Widens the coefficient bounds so that they also hold for every rim whose centre lies within
/// `centre_error` (Euclidean) of circle.center: only k0 = dist(c, axis)^2 - ... and the first
/// harmonic depend on the centre (docs/circle-cylinder.md, section 1). Every tier then proves
/// its answer for all those rims at once, the exact centre among them (rounded_point.hpp).
void widen_for_centre_error(RimDistancePolynomial& g, const Circle3& circle,
                            const Cylinder3& cylinder, double centre_error);

/// Outcome of the cheap test on the rim's reach before any root finding.
enum class RimReach {
  strictly_inside,   ///< dist(center, axis) + r < R: no rim point reaches the wall
  strictly_outside,  ///< dist(center, axis) - r > R: every rim point is beyond the wall
  undecided,
};

/// Proved with the running error bound of error_bounded.hpp: the answer is never wrong.
RimReach rim_reach(const Circle3& circle, const Cylinder3& cylinder);
/// The same with the magnitude guard already evaluated, proved for every centre within
/// `centre_error` of circle.center (rounded_point.hpp).
RimReach rim_reach(const Circle3& circle, const Cylinder3& cylinder, bool a_priori_bounds_apply,
                   double centre_error = 0.0);

}  // namespace clearjoint::geometry::detail
