// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Exact fallback of the circle-plane topology predicate (CGAL rationals).

#include "arithmetic/rounded_point.hpp"
#include "clearjoint/geometry/model/circle_plane_topology.hpp"
#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::geometry::detail {

struct CirclePlaneTopologyAndSide {
  CirclePlaneTopology topology;
  int side;  ///< PlaneSide as -1, 0, +1 (the sign the filters and CGAL compute)
};

/// Decides, exactly on the stored doubles: parallel normals (n_p x n_c = 0), the sign of
/// s = n_p . (c - p), and the sign of s^2 |n_c|^2 - r^2 |n_p x n_c|^2 (docs/circle-plane.md).
/// `centre` and `point`, when given, are the recipes of the exact rim centre and plane point that
/// circle.center and plane.point round (before the query's rescaling by 2^-scale_exponent).
CirclePlaneTopologyAndSide exact_circle_plane_topology(const Circle3& circle, const Plane3& plane,
                                                       const RoundedPoint* centre = nullptr,
                                                       const RoundedPoint* point = nullptr,
                                                       int scale_exponent = 0);

}  // namespace clearjoint::geometry::detail
