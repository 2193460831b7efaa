// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Circle3, Plane3 and Cylinder3: the exact sets their stored doubles describe.
///
/// A primitive means exactly the point set written below, evaluated in real arithmetic on the
/// stored doubles. Nothing is normalised on the way in: a normal or axis need not have unit
/// length, and every certified or exact answer is about that set, not about a rounded copy.

#include <string_view>

#include "clearjoint/geometry/arithmetic/vector3.hpp"
#include "clearjoint/validation_error.hpp"

namespace clearjoint::geometry {

/// A circle in space (a journal base rim): { x : normal . (x - center) = 0, |x - center| = radius }.
/// Preconditions (checked by validate()): finite fields, radius > 0, normal != 0.
struct Circle3 {
  Vector3 center;
  Vector3 normal;
  double radius = 0.0;
};

/// A plane (a bearing base): { x : normal . (x - point) = 0 }. The side normal points to is
/// "positive" (for a bearing base: outside the bearing). normal != 0, finite fields.
struct Plane3 {
  Vector3 point;
  Vector3 normal;
};

/// The lateral surface of an infinite circular cylinder (a bearing wall):
/// { x : |(x - axis_point) x axis|^2 = radius^2 |axis|^2 }. Points with larger distance to the
/// axis are "outside" (beyond the wall). axis != 0, radius > 0, finite fields.
struct Cylinder3 {
  Vector3 axis_point;
  Vector3 axis;
  double radius = 0.0;
};

/// Thrown for bad input to the kernel: a ValidationError whose field path names the field
/// ("circle.radius") and whose message its value, e.g. "circle.radius = -1: must be positive".
class InvalidInput : public ValidationError {
 public:
  using ValidationError::ValidationError;
};

/// Check a primitive; `name` prefixes the field in the message ("rim A" gives "rim A.radius").
void validate(const Circle3& circle, std::string_view name = "circle");
void validate(const Plane3& plane, std::string_view name = "plane");
void validate(const Cylinder3& cylinder, std::string_view name = "cylinder");

/// The rim's angular parametrisation, fixed once for all queries:
///   x(theta) = center + radius (cos(theta) u + sin(theta) v),
/// with u = (normal x e_k)/|normal x e_k|, k the index of the smallest |normal_k| (first on ties),
/// and v = normal/|normal| x u, so (u, v, normal) is right-handed. Angles reported by the queries
/// are in this parametrisation, in [0, 2 pi). The stored u and v are rounded to double.
struct CircleFrame {
  Vector3 u;
  Vector3 v;
};
CircleFrame frame_of(const Circle3& circle);

/// The rim point at `angle` (double arithmetic, a few ulps of |center| + radius).
Vector3 point_at(const Circle3& circle, const CircleFrame& frame, double angle);

}  // namespace clearjoint::geometry
