// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A journal rim against a bearing base plane: axial contact, paper eqs. (11)-(15).

#include <array>
#include <string_view>

#include "clearjoint/geometry/certificate.hpp"
#include "clearjoint/geometry/enum_table.hpp"
#include "clearjoint/geometry/intersection_options.hpp"
#include "clearjoint/geometry/primitives.hpp"
#include "clearjoint/geometry/rim_arc.hpp"

namespace clearjoint::geometry {

/// Which side of the plane the circle lies on (apart from a tangent point).
enum class PlaneSide : signed char {
  negative = -1,  ///< away from the side the plane normal points to
  none = 0,       ///< on both sides (two_crossings) or in the plane (circle_in_plane)
  positive = 1,   ///< on the side the plane normal points to (for a bearing base: outside)
};

enum class CirclePlaneTopology {
  disjoint,        ///< no common point; `side` says where the circle is
  tangent,         ///< one common point of multiplicity 2; the rest of the circle is on `side`
  two_crossings,   ///< two distinct crossings, the circle passes through the plane
  circle_in_plane  ///< every rim point lies in the plane
};

template <>
struct EnumTable<CirclePlaneTopology> {
  using T = CirclePlaneTopology;
  static constexpr std::string_view type_name = "CirclePlaneTopology";
  static constexpr auto entries = std::to_array({
      named_entry(T::disjoint, "disjoint", "no common point; side says where the circle is"),
      named_entry(T::tangent, "tangent", "one common point of multiplicity 2"),
      named_entry(T::two_crossings, "two_crossings", "the circle passes through the plane"),
      named_entry(T::circle_in_plane, "circle_in_plane", "every rim point lies in the plane"),
  });
};
static_assert(entries_in_code_order<CirclePlaneTopology>());

/// The key: "disjoint", "tangent", "two_crossings", "circle_in_plane".
constexpr std::string_view to_string(CirclePlaneTopology topology) noexcept { return key_of(topology); }

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
