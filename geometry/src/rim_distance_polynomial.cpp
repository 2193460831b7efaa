#include "rim_distance_polynomial.hpp"

#include <cmath>

#include "primitives_detail.hpp"

namespace clearjoint::geometry::detail {
namespace {

BoundedVector3 exact(const Vector3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

RimDistancePolynomial rim_distance_polynomial(const Circle3& circle, const Cylinder3& cylinder) {
  // Notation of docs/circle-cylinder.md: q = c - p (rim centre from axis point), d the axis,
  // n the rim normal, u' = n x e_k (exact), v' = n x u'; hats are unit vectors; D = |d|^2.
  const BoundedVector3 q = exact(circle.center) - exact(cylinder.axis_point);
  const BoundedVector3 d = exact(cylinder.axis);
  const BoundedVector3 n = exact(circle.normal);
  const Vector3 u_double = circle.normal.cross(Vector3::Unit(frame_axis_index(circle.normal)));
  const BoundedVector3 u = exact(u_double);  // exact: components are +-n_j or 0
  const BoundedVector3 v = cross(n, u);

  const Bounded axis_norm2 = squared_norm(d);
  // Reciprocals once: a bounded division costs several multiplications.
  const Bounded inverse_axis_norm2 = Bounded(1.0) / axis_norm2;
  const Bounded inverse_u_norm = Bounded(1.0) / sqrt(squared_norm(u));
  const Bounded inverse_v_norm = Bounded(1.0) / sqrt(squared_norm(v));
  const Bounded r = circle.radius;
  const Bounded r2 = r * r;

  // The offset projected off the axis before squaring: A = q x d, |A|^2 / D = dist(c, axis)^2.
  const BoundedVector3 offset_perp = cross(q, d);
  // (q x d).(u x d) = (q.u) D - (q.d)(u.d) without its cancellation.
  const Bounded first_cos = dot(offset_perp, cross(u, d)) * inverse_u_norm;
  const Bounded first_sin = dot(offset_perp, cross(v, d)) * inverse_v_norm;
  const Bounded axis_along_u = dot(u, d) * inverse_u_norm;  // u_hat . d
  const Bounded axis_along_v = dot(v, d) * inverse_v_norm;  // v_hat . d
  // |n_hat x d|^2 = D sin^2(tilt), computed as a cross product: no cancellation at small tilt.
  const Bounded tilt_term = squared_norm(cross(n, d)) / squared_norm(n);
  // Radii difference as (r - R)(r + R): r - R is exact when the radii are within a factor 2.
  const Bounded radii_term = (r - Bounded(cylinder.radius)) * (r + Bounded(cylinder.radius));

  RimDistancePolynomial g;
  g.k[0] = (squared_norm(offset_perp) - Bounded(0.5) * r2 * tilt_term) * inverse_axis_norm2 +
           radii_term;
  g.k[1] = Bounded(2.0) * r * first_cos * inverse_axis_norm2;
  g.k[2] = Bounded(2.0) * r * first_sin * inverse_axis_norm2;
  g.k[3] = Bounded(0.5) * r2 * (axis_along_v * axis_along_v - axis_along_u * axis_along_u) *
           inverse_axis_norm2;
  g.k[4] = -(r2 * axis_along_u * axis_along_v) * inverse_axis_norm2;
  return g;
}

Bounded RimDistancePolynomial::value(double theta) const {
  const BoundedSinCos t = sincos_of(theta);
  const Bounded cos2 = (t.cos - t.sin) * (t.cos + t.sin);
  const Bounded sin2 = Bounded(2.0) * t.sin * t.cos;
  return k[0] + k[1] * t.cos + k[2] * t.sin + k[3] * cos2 + k[4] * sin2;
}

Bounded RimDistancePolynomial::derivative(double theta) const {
  const BoundedSinCos t = sincos_of(theta);
  const Bounded cos2 = (t.cos - t.sin) * (t.cos + t.sin);
  const Bounded sin2 = Bounded(2.0) * t.sin * t.cos;
  return k[2] * t.cos - k[1] * t.sin + Bounded(2.0) * (k[4] * cos2 - k[3] * sin2);
}

double RimDistancePolynomial::approximate_value(double theta) const {
  const double c = std::cos(theta), s = std::sin(theta);
  return k[0].value + k[1].value * c + k[2].value * s + k[3].value * (c - s) * (c + s) +
         k[4].value * 2 * s * c;
}

double RimDistancePolynomial::approximate_derivative(double theta) const {
  const double c = std::cos(theta), s = std::sin(theta);
  return k[2].value * c - k[1].value * s + 2 * (k[4].value * (c - s) * (c + s) - k[3].value * 2 * s * c);
}

double RimDistancePolynomial::approximate_newton_step(double theta) const {
  const double c = std::cos(theta), s = std::sin(theta);
  const double cos2 = (c - s) * (c + s), sin2 = 2 * s * c;
  const double value = k[0].value + k[1].value * c + k[2].value * s + k[3].value * cos2 + k[4].value * sin2;
  const double slope = k[2].value * c - k[1].value * s + 2 * (k[4].value * cos2 - k[3].value * sin2);
  return value / slope;
}

double RimDistancePolynomial::second_derivative_bound() const {
  // |g''| <= |first harmonic| + 4 |second harmonic|, each harmonic's amplitude bounded by the
  // hypot of its (enclosed) coefficients.
  auto high = [](const Bounded& x) { return std::fabs(x.value) + x.error; };
  const double bound = std::hypot(high(k[1]), high(k[2])) + 4 * std::hypot(high(k[3]), high(k[4]));
  return bound * (1 + 8 * kUnitRoundoff) + kUnderflowError;
}

RimReach rim_reach(const Circle3& circle, const Cylinder3& cylinder) {
  // dist(x, axis) lies within dist(c, axis) +- r for every rim point x. Compare squares:
  // |q x d|^2 against (R -+ r)^2 |d|^2.
  const BoundedVector3 q = exact(circle.center) - exact(cylinder.axis_point);
  const BoundedVector3 d = exact(cylinder.axis);
  const Bounded offset2 = squared_norm(cross(q, d));
  const Bounded axis_norm2 = squared_norm(d);
  const double R = cylinder.radius, r = circle.radius;
  if (R > r) {
    const Bounded gap = Bounded(R) - Bounded(r);
    if ((gap * gap * axis_norm2 - offset2).sign() > 0) return RimReach::strictly_inside;
  }
  const Bounded reach = Bounded(R) + Bounded(r);
  if ((offset2 - reach * reach * axis_norm2).sign() > 0) return RimReach::strictly_outside;
  return RimReach::undecided;
}

}  // namespace clearjoint::geometry::detail
