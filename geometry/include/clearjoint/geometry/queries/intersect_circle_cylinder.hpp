// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A journal rim against the bearing's lateral wall: radial contact, paper eqs. (16)-(21).
///
/// The paper solves eqs. (16)-(17) with Newton-Raphson and assumes at most two crossings. Here all
/// crossings (0 to 4) are found, each is proved, and the absence of others is proved; where
/// floating point cannot decide (tangency), exact rational arithmetic decides.
/// docs/circle-cylinder.md derives the method.

#include <array>
#include <string_view>
#include <tuple>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/enum_table.hpp"
#include "clearjoint/geometry/model/intersection_options.hpp"
#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/geometry/model/rim_arc.hpp"
#include "clearjoint/geometry/model/field_lists.hpp"

namespace clearjoint::geometry {

enum class CircleCylinderTopology {
  inside,      ///< no common point, every rim point strictly closer to the axis than the radius
  outside,     ///< no common point, every rim point strictly farther (the rim is beyond the wall)
  crossing,    ///< 1 to 4 distinct common points, each with its multiplicity
  on_surface   ///< every rim point lies on the cylinder (coaxial, equal radii)
};

template <>
struct EnumTable<CircleCylinderTopology> {
  using T = CircleCylinderTopology;
  static constexpr std::string_view type_name = "CircleCylinderTopology";
  static constexpr auto entries = std::to_array({
      named_entry(T::inside, "inside", "every rim point strictly inside the wall"),
      named_entry(T::outside, "outside", "every rim point strictly beyond the wall"),
      named_entry(T::crossing, "crossing", "1 to 4 distinct common points"),
      named_entry(T::on_surface, "on_surface", "coaxial with equal radii"),
  });
};
static_assert(entries_in_code_order<CircleCylinderTopology>());

/// The key: "inside", "outside", "crossing", "on_surface".
constexpr std::string_view to_string(CircleCylinderTopology topology) noexcept { return key_of(topology); }

struct CircleCylinderIntersection {
  CircleCylinderTopology topology = CircleCylinderTopology::inside;
  /// Sorted by angle. Multiplicities add up to 0, 2 or 4 (a tangency counts 2).
  std::array<RimCrossing, 4> crossings{};
  int crossing_count = 0;
  /// Maximal arcs of rim points strictly outside the cylinder (beyond the wall). Two arcs mean
  /// the rim crosses the wall four times, which the paper's model does not cover.
  std::array<RimArc, 2> penetration_arcs{};
  int arc_count = 0;
  Certificate certificate{};

  /// Sum of multiplicities: the number of roots of the rim's distance function, counted properly.
  int root_count() const noexcept;
};

/// Its field list (model/field_lists.hpp): a member added above needs its line here.
template <>
struct ResultFields<CircleCylinderIntersection> {
  using Y = CircleCylinderIntersection;
  static constexpr std::string_view type_name = "CircleCylinderIntersection";
  static constexpr std::tuple fields{
      fields::plain("topology", &Y::topology),
      fields::list("crossings", &Y::crossings, &Y::crossing_count, "sorted by angle; multiplicities add up to 0, 2 or 4"),
      fields::list("penetration_arcs", &Y::penetration_arcs, &Y::arc_count,
                   "maximal arcs strictly beyond the wall; two arcs are beyond the paper's model"),
      fields::plain("certificate", &Y::certificate)};
};
static_assert(detail::lists_every_member<CircleCylinderIntersection>(), "a member of CircleCylinderIntersection is missing from its field list");

/// Intersect a circle with a cylinder's lateral surface. Throws InvalidInput on bad primitives.
CircleCylinderIntersection intersect_circle_cylinder(const Circle3& circle,
                                                     const Cylinder3& cylinder,
                                                     const IntersectionOptions& options = {});

}  // namespace clearjoint::geometry
