// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Helpers shared by the geometry tests: rigid motions and unit changes of primitives, and an
/// independent long-double evaluation of frame_of's documented parametrisation.

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::geometry::testing {

inline constexpr double kTwoPi = 2 * std::numbers::pi;

/// A rigid motion x -> rotation x + translation.
struct RigidMotion {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Vector3 translation = Vector3::Zero();

  Vector3 point(const Vector3& x) const { return rotation * x + translation; }
  Vector3 direction(const Vector3& d) const { return rotation * d; }
  Circle3 operator()(const Circle3& c) const { return {point(c.center), direction(c.normal), c.radius}; }
  Plane3 operator()(const Plane3& p) const { return {point(p.point), direction(p.normal)}; }
  Cylinder3 operator()(const Cylinder3& c) const {
    return {point(c.axis_point), direction(c.axis), c.radius};
  }
};

/// A uniformly distributed rotation (normalised Gaussian quaternion) and a translation with
/// coordinates uniform in [-reach, reach].
template <class Rng>
RigidMotion random_motion(Rng& rng, double reach) {
  std::normal_distribution<double> gauss;
  Eigen::Quaterniond q(gauss(rng), gauss(rng), gauss(rng), gauss(rng));
  q.normalize();
  std::uniform_real_distribution<double> shift(-reach, reach);
  return {q.toRotationMatrix(), Vector3(shift(rng), shift(rng), shift(rng))};
}

/// The 24 rotations that map the coordinate axes onto themselves (signed permutation matrices
/// with determinant +1). Applied to integer data they are exact, so tangencies stay tangencies.
inline std::vector<RigidMotion> axis_rotations() {
  std::vector<RigidMotion> out;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& p : perms) {
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
      for (int row = 0; row < 3; ++row) m(row, p[row]) = (signs >> row) & 1 ? -1.0 : 1.0;
      if (m.determinant() > 0) out.push_back({m, Vector3::Zero()});
    }
  }
  return out;
}

/// A change of units: every length times `factor`; directions are left alone.
inline Circle3 scaled(const Circle3& c, double factor) {
  return {c.center * factor, c.normal, c.radius * factor};
}
inline Plane3 scaled(const Plane3& p, double factor) { return {p.point * factor, p.normal}; }
inline Cylinder3 scaled(const Cylinder3& c, double factor) {
  return {c.axis_point * factor, c.axis, c.radius * factor};
}

/// frame_of's documented frame, evaluated independently in long double.
struct LongFrame {
  long double u[3];
  long double v[3];
};
inline LongFrame documented_frame(const Vector3& normal) {
  int k = 0;
  if (std::abs(normal.y()) < std::abs(normal.x())) k = 1;
  if (std::abs(normal.z()) < std::abs(normal[k])) k = 2;
  const long double n[3] = {normal.x(), normal.y(), normal.z()};
  long double e[3] = {0, 0, 0};
  e[k] = 1;
  LongFrame f;
  const long double u[3] = {n[1] * e[2] - n[2] * e[1], n[2] * e[0] - n[0] * e[2],
                            n[0] * e[1] - n[1] * e[0]};
  const long double un = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  const long double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int i = 0; i < 3; ++i) f.u[i] = u[i] / un;
  f.v[0] = (n[1] * f.u[2] - n[2] * f.u[1]) / nn;
  f.v[1] = (n[2] * f.u[0] - n[0] * f.u[2]) / nn;
  f.v[2] = (n[0] * f.u[1] - n[1] * f.u[0]) / nn;
  return f;
}

/// The documented rim angle of a point on (or near) the rim, in [0, 2 pi).
inline double documented_angle(const Circle3& c, const Vector3& point) {
  const LongFrame f = documented_frame(c.normal);
  long double du = 0, dv = 0;
  for (int i = 0; i < 3; ++i) {
    const long double d = static_cast<long double>(point[i]) - c.center[i];
    du += d * f.u[i];
    dv += d * f.v[i];
  }
  long double a = std::atan2(dv, du);
  if (a < 0) a += 2 * std::numbers::pi_v<long double>;
  const double rounded = static_cast<double>(a);
  return rounded >= kTwoPi ? 0.0 : rounded;
}

/// The documented rim point at `angle`, in long double then rounded.
inline Vector3 documented_point(const Circle3& c, long double angle) {
  const LongFrame f = documented_frame(c.normal);
  Vector3 p;
  for (int i = 0; i < 3; ++i) {
    p[i] = static_cast<double>(c.center[i] +
                               c.radius * (std::cos(angle) * f.u[i] + std::sin(angle) * f.v[i]));
  }
  return p;
}

/// Distance between two angles on the circle, in [0, pi].
inline double circular_distance(double a, double b) {
  return std::abs(std::remainder(a - b, kTwoPi));
}

}  // namespace clearjoint::geometry::testing
