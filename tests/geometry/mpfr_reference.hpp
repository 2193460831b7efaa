// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Independent 256-bit MPFR references for the tests of the kernel's internal pieces: the rim
/// parametrisation documented in primitives.hpp, the squared distance to a cylinder axis, and
/// a trigonometric polynomial of degree 2. Nothing here calls the code under test.

#include <boost/multiprecision/mpfr.hpp>

#include <array>
#include <cmath>

#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::geometry::internal_testing {

using Real = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<256>,
                                           boost::multiprecision::et_off>;

/// The references below chain at most a few dozen 256-bit roundings, so their own error is far
/// below 2^-240 times the largest intermediate magnitude. Containment checks allow this much on
/// top of the bound under test (it is ~2^190 times smaller than one double rounding).
inline const double kReferenceRelativeError = 0x1p-240;

inline Real pi() { return boost::multiprecision::acos(Real(-1)); }
inline Real two_pi() { return 2 * pi(); }

struct RealVector3 {
  Real x, y, z;
};
inline RealVector3 to_real(const Vector3& v) { return {Real(v.x()), Real(v.y()), Real(v.z())}; }
inline RealVector3 operator+(const RealVector3& a, const RealVector3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline RealVector3 operator-(const RealVector3& a, const RealVector3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline RealVector3 operator*(const Real& s, const RealVector3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Real dot(const RealVector3& a, const RealVector3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline RealVector3 cross(const RealVector3& a, const RealVector3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Real norm(const RealVector3& a) { return boost::multiprecision::sqrt(dot(a, a)); }

/// The frame documented in primitives.hpp, in exact-then-256-bit arithmetic:
/// u = (n x e_k)/|n x e_k|, k the index of the smallest |n_k| (first on ties), v = n/|n| x u.
struct RealFrame {
  RealVector3 u, v;
};
inline RealFrame documented_frame(const Vector3& normal) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(normal[i]) < std::fabs(normal[k])) k = i;
  const RealVector3 n = to_real(normal);
  RealVector3 e{Real(0), Real(0), Real(0)};
  (k == 0 ? e.x : k == 1 ? e.y : e.z) = 1;
  const RealVector3 u_prime = cross(n, e);
  const RealVector3 u = Real(1) / norm(u_prime) * u_prime;
  const RealVector3 v = cross(Real(1) / norm(n) * n, u);
  return {u, v};
}

inline RealVector3 rim_point(const Circle3& circle, const RealFrame& frame, const Real& theta) {
  return to_real(circle.center) +
         Real(circle.radius) * (cos(theta) * frame.u + sin(theta) * frame.v);
}

/// dist(x, axis)^2 - R^2 straight from the definition in primitives.hpp.
inline Real axis_distance_excess(const RealVector3& x, const Cylinder3& cylinder) {
  const RealVector3 d = to_real(cylinder.axis);
  const RealVector3 w = cross(x - to_real(cylinder.axis_point), d);
  return dot(w, w) / dot(d, d) - Real(cylinder.radius) * Real(cylinder.radius);
}

/// g(theta) of the stored primitives, from the definition (not from any coefficient formula).
inline Real rim_distance_excess(const Circle3& circle, const Cylinder3& cylinder,
                                const Real& theta) {
  return axis_distance_excess(rim_point(circle, documented_frame(circle.normal), theta), cylinder);
}

/// Exact dist(c, axis) of the rim centre.
inline Real centre_axis_distance(const Circle3& circle, const Cylinder3& cylinder) {
  const RealVector3 d = to_real(cylinder.axis);
  const RealVector3 w = cross(to_real(circle.center) - to_real(cylinder.axis_point), d);
  return boost::multiprecision::sqrt(dot(w, w) / dot(d, d));
}

/// k0 + k1 cos t + k2 sin t + k3 cos 2t + k4 sin 2t with real coefficients.
inline Real trig_polynomial(const std::array<Real, 5>& k, const Real& t) {
  const Real c = cos(t), s = sin(t);
  return k[0] + k[1] * c + k[2] * s + k[3] * (c - s) * (c + s) + k[4] * 2 * s * c;
}
inline Real trig_polynomial_derivative(const std::array<Real, 5>& k, const Real& t) {
  return -k[1] * sin(t) + k[2] * cos(t) - 2 * k[3] * sin(2 * t) + 2 * k[4] * cos(2 * t);
}

/// Distance between two angles on the circle, in [0, pi].
inline Real circular_gap(const Real& a, const Real& b) {
  const Real period = two_pi();
  Real gap = fmod(a - b, period);
  if (gap < 0) gap += period;
  if (gap > period / 2) gap = period - gap;
  return gap;
}

inline int sign_of(const Real& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

}  // namespace clearjoint::geometry::internal_testing
