#pragma once
// Exact fallback of the circle-plane topology predicate (CGAL rationals).

#include "clearjoint/geometry/intersect_circle_plane.hpp"

namespace clearjoint::geometry::detail {

struct CirclePlaneTopologyAndSide {
  CirclePlaneTopology topology;
  int side;
};

/// Decides, exactly on the stored doubles: parallel normals (n_p x n_c = 0), the sign of
/// s = n_p . (c - p), and the sign of s^2 |n_c|^2 - r^2 |n_p x n_c|^2 (docs/circle-plane.md).
CirclePlaneTopologyAndSide exact_circle_plane_topology(const Circle3& circle, const Plane3& plane);

}  // namespace clearjoint::geometry::detail
