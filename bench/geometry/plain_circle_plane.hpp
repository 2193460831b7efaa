// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A measuring stick, not a query to use: the circle-plane answer (topology, side, depth of the
// deepest rim point, two crossing angles and points) in plain double with no error bound and no
// proof, written as cheaply as we know how. Timed beside intersect_circle_plane on the same inputs,
// it says how far the certified query is from the arithmetic its contract needs
// (docs/reports/benchmarks-kernel.md). Same formulas as
// geometry/src/queries/intersect_circle_plane.cpp and docs/circle-plane.md (paper eqs. 11-15);
// tangency and a rim in the plane are read off exact zeros of the computed values, so near them its
// answers can be wrong: that is the point of comparing it with the certified query, not a shortcut
// the library may take.

#include <cmath>
#include <numbers>

#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::bench {

struct PlainCirclePlane {
  geometry::CirclePlaneTopology topology = geometry::CirclePlaneTopology::disjoint;
  int side = 0;
  double max_signed_distance = 0.0;
  double s = 0.0;  ///< n_p . (c - p), kept for the crossings
  int crossing_count = 0;
  double angles[2] = {0.0, 0.0};
  geometry::Vector3 points[2];
};

/// The topology and the depth only: s, w = n_p x n_c, the sign of s^2 |n_c|^2 - r^2 |w|^2 and
/// (s + r |w| / |n_c|) / |n_p|.
inline PlainCirclePlane plain_circle_plane_depth(const geometry::Circle3& circle, const geometry::Plane3& plane) {
  using geometry::CirclePlaneTopology;
  const geometry::Vector3& np = plane.normal;
  const geometry::Vector3& nc = circle.normal;
  const double s = np.dot(circle.center - plane.point);
  const double w2 = np.cross(nc).squaredNorm(), nc2 = nc.squaredNorm();
  const double r = circle.radius;
  const double discriminant = s * s * nc2 - r * r * w2;
  PlainCirclePlane out;
  out.s = s;
  out.side = s > 0 ? 1 : (s < 0 ? -1 : 0);
  out.max_signed_distance = (s + r * std::sqrt(w2 / nc2)) / std::sqrt(np.squaredNorm());
  if (w2 == 0.0 && s == 0.0) out.topology = CirclePlaneTopology::circle_in_plane;
  else if (discriminant > 0.0 || w2 == 0.0) out.topology = CirclePlaneTopology::disjoint;
  else if (discriminant == 0.0) out.topology = CirclePlaneTopology::tangent;
  else out.topology = CirclePlaneTopology::two_crossings;
  return out;
}

/// The whole answer: for two crossings also theta_m -+ beta and their points, the angle of the
/// plane normal's in-plane part from the rounded frame (atan2), cos(beta) = -s / (r |P n_p|), the
/// points by angle addition (no sine or cosine calls).
inline PlainCirclePlane plain_circle_plane(const geometry::Circle3& circle, const geometry::Plane3& plane) {
  PlainCirclePlane out = plain_circle_plane_depth(circle, plane);
  if (out.topology != geometry::CirclePlaneTopology::two_crossings) return out;
  const geometry::Vector3& np = plane.normal;
  const geometry::CircleFrame frame = geometry::frame_of(circle);
  const double along_u = np.dot(frame.u), along_v = np.dot(frame.v);
  const double in_plane = std::sqrt(along_u * along_u + along_v * along_v);  // |P n_p|
  const double theta_m = std::atan2(along_v, along_u);
  const double cos_m = along_u / in_plane, sin_m = along_v / in_plane;
  const double cos_beta = -out.s / (circle.radius * in_plane);
  const double beta = std::acos(cos_beta);
  const double sin_beta = std::sqrt((1.0 - cos_beta) * (1.0 + cos_beta));
  const double cos_angle[2] = {cos_m * cos_beta + sin_m * sin_beta, cos_m * cos_beta - sin_m * sin_beta};
  const double sin_angle[2] = {sin_m * cos_beta - cos_m * sin_beta, sin_m * cos_beta + cos_m * sin_beta};
  out.crossing_count = 2;
  for (int i = 0; i < 2; ++i) {
    out.angles[i] = theta_m + (i == 0 ? -beta : beta);
    out.points[i] = circle.center + circle.radius * (cos_angle[i] * frame.u + sin_angle[i] * frame.v);
  }
  return out;
}

}  // namespace clearjoint::bench
