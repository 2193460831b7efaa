// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A journal rim against a bearing base plane: axial contact, paper eqs. (11)-(15).

#include <array>
#include <tuple>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/circle_plane_topology.hpp"
#include "clearjoint/geometry/model/intersection_options.hpp"
#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/geometry/model/rim_arc.hpp"
#include "clearjoint/geometry/model/field_lists.hpp"

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

/// Its field list (model/field_lists.hpp): a member added above needs its line here.
template <>
struct ResultFields<CirclePlaneIntersection> {
  using P = CirclePlaneIntersection;
  static constexpr std::string_view type_name = "CirclePlaneIntersection";
  static constexpr std::tuple fields{
      fields::plain("topology", &P::topology),
      fields::plain("side", &P::side,
                    "PlaneSide as an int. +1: the circle lies on the side the plane normal points to, -1 the "
                    "other; 0 for two_crossings and circle_in_plane"),
      fields::list("crossings", &P::crossings, &P::crossing_count),
      fields::optional("penetration", &P::penetration, &P::has_penetration,
                       "the rim points strictly on the normal's side (a RimArc), or None"),
      fields::plain("max_signed_distance", &P::max_signed_distance,
                    "largest signed distance of a rim point from the plane, positive on the normal's side"),
      fields::bound("max_signed_distance_error", &P::max_signed_distance_error),
      fields::plain("certificate", &P::certificate)};
};
static_assert(detail::lists_every_member<CirclePlaneIntersection>(), "a member of CirclePlaneIntersection is missing from its field list");

/// Intersect a circle with a plane. The topology is decided by an exact predicate (a
/// floating-point filter with a derived error bound, then CGAL rationals); the crossings are
/// computed in double with a certified error bound. Throws InvalidInput on bad primitives.
CirclePlaneIntersection intersect_circle_plane(const Circle3& circle, const Plane3& plane,
                                               const IntersectionOptions& options = {});

}  // namespace clearjoint::geometry
