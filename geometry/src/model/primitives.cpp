// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/model/primitives.hpp"

#include <cmath>

#include "model/input_checks.hpp"
#include "model/primitives_detail.hpp"

namespace clearjoint::geometry {
namespace {

using detail::require_finite;
using detail::require_nonzero;
using detail::require_positive;

/// x / |x|. The plain formula when |x|^2 is a normal double, as x times one reciprocal (one
/// division instead of three; a rounding more per component, within the frame's documented few
/// ulps); Eigen's stableNormalized (which rescales first, at several times the cost) when |x|^2
/// would under- or overflow.
Vector3 unit(const Vector3& x) {
  constexpr double kSmallestSafeSquare = 0x1p-1000, kLargestSafeSquare = 0x1p1000;
  const double squared = x.squaredNorm();
  if (squared > kSmallestSafeSquare && squared < kLargestSafeSquare) return x * (1.0 / std::sqrt(squared));
  return x.stableNormalized();
}

}  // namespace

void validate(const Circle3& circle, std::string_view name) {
  require_finite(circle.center, name, "center");
  require_finite(circle.normal, name, "normal");
  require_nonzero(circle.normal, name, "normal");
  require_positive(circle.radius, name, "radius");
}

void validate(const Plane3& plane, std::string_view name) {
  require_finite(plane.point, name, "point");
  require_finite(plane.normal, name, "normal");
  require_nonzero(plane.normal, name, "normal");
}

void validate(const Cylinder3& cylinder, std::string_view name) {
  require_finite(cylinder.axis_point, name, "axis_point");
  require_finite(cylinder.axis, name, "axis");
  require_nonzero(cylinder.axis, name, "axis");
  require_positive(cylinder.radius, name, "radius");
}

CircleFrame frame_of(const Circle3& circle) {
  // u' = normal x e_k is exact in double (its components are +-normal_j or 0), see primitives.hpp.
  const Vector3 u_unnormalised = circle.normal.cross(Vector3::Unit(frame_axis_index(circle.normal)));
  const Vector3 u = unit(u_unnormalised);
  const Vector3 v = unit(circle.normal).cross(u);
  return {u, v};
}

Vector3 point_at(const Circle3& circle, const CircleFrame& frame, double angle) {
  return circle.center + circle.radius * (std::cos(angle) * frame.u + std::sin(angle) * frame.v);
}

}  // namespace clearjoint::geometry
