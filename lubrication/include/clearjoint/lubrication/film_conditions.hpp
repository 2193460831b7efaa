// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// What the film is made of and how it is fed: the lubricant, the cavitation model and the oil
/// supply. Pressures are gauge pressures (relative to the ambient pressure at the film's ends).

#include <array>
#include <string_view>

#include "clearjoint/geometry/arithmetic/vector3.hpp"
#include "clearjoint/geometry/model/enum_table.hpp"

namespace clearjoint::lubrication {

using geometry::Vector3;

/// An incompressible, isoviscous (Newtonian, constant viscosity) lubricant.
struct Lubricant {
  double viscosity = 0.0;  ///< dynamic viscosity eta, Pa s (any unit consistent with the lengths)
};

/// How the film ruptures where the Reynolds pressure would fall below the ambient pressure.
enum class CavitationModel {
  /// Half-Sommerfeld (Guembel): solve the Reynolds equation everywhere, then discard negative
  /// gauge pressures. Does not conserve mass at the film's rupture and reformation.
  half_sommerfeld,
  /// Elrod-Adams / JFO: the film ruptures at ambient pressure with zero pressure gradient
  /// (the Reynolds, or Swift-Stieber, condition) and reforms where the striated flow carried
  /// through the cavity refills the gap; mass is conserved across both boundaries.
  mass_conserving,
};

}  // namespace clearjoint::lubrication

/// Keys "half_sommerfeld", "mass_conserving": what every front end reads and writes (model files,
/// Python, the command line).
template <>
struct clearjoint::geometry::EnumTable<clearjoint::lubrication::CavitationModel> {
  using M = clearjoint::lubrication::CavitationModel;
  static constexpr std::string_view type_name = "CavitationModel";
  static constexpr auto entries = std::to_array({
      named_entry(M::half_sommerfeld, "half_sommerfeld", "half-Sommerfeld (Guembel)"),
      named_entry(M::mass_conserving, "mass_conserving", "mass-conserving (Elrod-Adams, JFO)"),
  });
};
static_assert(clearjoint::geometry::entries_in_code_order<clearjoint::lubrication::CavitationModel>());

namespace clearjoint::lubrication {

/// The key of the model's entry in its table.
std::string_view to_string(CavitationModel model) noexcept;

/// Where the oil comes from. A mass-conserving film needs a supply: fed only by its ends, whose
/// flow is outward wherever the film carries pressure, it would drain (docs/lubrication.md).
struct OilSupply {
  enum class Kind {
    none,          ///< an enclosed film, flooded at ambient pressure at its two ends only
    axial_groove,  ///< an axial line groove along the whole film at supply_pressure
  };
  Kind kind = Kind::none;
  /// Direction from the bearing's axis to the groove, in W; only its part perpendicular to the
  /// bearing's axis counts. A groove is fixed in the bearing: the caller turns it with the bearing.
  Vector3 groove_direction_W = Vector3::UnitX();
  double supply_pressure = 0.0;  ///< gauge, Pa; >= 0
};

}  // namespace clearjoint::lubrication

template <>
struct clearjoint::geometry::EnumTable<clearjoint::lubrication::OilSupply::Kind> {
  using K = clearjoint::lubrication::OilSupply::Kind;
  static constexpr std::string_view type_name = "OilSupplyKind";
  static constexpr auto entries = std::to_array({
      named_entry(K::none, "none", "enclosed film, fed at its ends"),
      named_entry(K::axial_groove, "axial_groove", "axial line groove at the supply pressure"),
  });
};
static_assert(clearjoint::geometry::entries_in_code_order<clearjoint::lubrication::OilSupply::Kind>());

namespace clearjoint::lubrication {

/// Throw geometry::InvalidInput naming the field for a non-finite or non-positive viscosity.
void validate(const Lubricant& lubricant, const char* name = "lubricant");
/// Throw geometry::InvalidInput for a negative or non-finite supply pressure or, for a groove, a
/// non-finite or zero direction.
void validate(const OilSupply& supply, const char* name = "supply");

}  // namespace clearjoint::lubrication
