// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// How a journal rim meets a bearing base plane: the topology and side of
/// intersect_circle_plane's answer (intersect_circle_plane.hpp), on their own so that the kernel's
/// exact tier can name them without the query.

#include <array>
#include <string_view>

#include "clearjoint/geometry/model/enum_table.hpp"

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

}  // namespace clearjoint::geometry
