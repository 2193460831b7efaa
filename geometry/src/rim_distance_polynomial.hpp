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
struct RimDistancePolynomial {
  std::array<Bounded, 5> k;

  Bounded value(double theta) const;
  Bounded derivative(double theta) const;
  /// Plain double evaluation, for Newton steps (no error bound).
  double approximate_value(double theta) const;
  double approximate_derivative(double theta) const;
  /// g / g' at theta from one sine-cosine evaluation (the Newton step).
  double approximate_newton_step(double theta) const;
  /// Bound on |g''| over all angles: hypot(k1, k2) + 4 hypot(k3, k4) with coefficient errors.
  double second_derivative_bound() const;
};

RimDistancePolynomial rim_distance_polynomial(const Circle3& circle, const Cylinder3& cylinder);

/// Outcome of the cheap test on the rim's reach before any root finding.
enum class RimReach {
  strictly_inside,   ///< dist(center, axis) + r < R: no rim point reaches the wall
  strictly_outside,  ///< dist(center, axis) - r > R: every rim point is beyond the wall
  undecided,
};

/// Proved with the running error bound of error_bounded.hpp: the answer is never wrong.
RimReach rim_reach(const Circle3& circle, const Cylinder3& cylinder);

}  // namespace clearjoint::geometry::detail
