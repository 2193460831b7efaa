// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A journal rim against a bearing base plane: axial contact, paper eqs. (11)-(15).

#include <array>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/circle_plane_topology.hpp"
#include "clearjoint/geometry/model/intersection_options.hpp"
#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/geometry/model/rim_arc.hpp"

namespace clearjoint::geometry {

struct CirclePlaneIntersection {
  CirclePlaneTopology topology = CirclePlaneTopology::disjoint;
  /// Where the circle lies (disjoint, tangent); PlaneSide::none for two_crossings and
  /// circle_in_plane.
  PlaneSide side = PlaneSide::none;
  std::array<RimCrossing, 2> crossings{};
  int crossing_count = 0;
  /// The rim points strictly on the positive side (the penetration arc when the normal points
  /// out of the bearing). Empty for disjoint on the negative side, tangent, circle_in_plane.
  RimArc penetration{};
  bool has_penetration = false;
  /// Largest signed distance of a rim point from the plane (metres, positive on the normal's
  /// side): the penetration depth of the deepest rim point, which is the middle of `penetration`.
  double max_signed_distance = 0.0;
  double max_signed_distance_error = kNoErrorBound;
  /// Covers the topology, the crossings and the distance.
  Certificate certificate{};
};

/// Intersect a circle with a plane. The topology is decided by an exact predicate (a
/// floating-point filter with a derived error bound, then CGAL rationals); the crossings are
/// computed in double with a certified error bound. Throws InvalidInput on bad primitives.
CirclePlaneIntersection intersect_circle_plane(const Circle3& circle, const Plane3& plane,
                                               const IntersectionOptions& options = {});

}  // namespace clearjoint::geometry
