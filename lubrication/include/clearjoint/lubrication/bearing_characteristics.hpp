// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The handbook query: a plain 360-degree journal bearing's non-dimensional characteristics.

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "clearjoint/lubrication/film_conditions.hpp"
#include "clearjoint/lubrication/reynolds_grid.hpp"

namespace clearjoint::lubrication {

enum class BearingMotion {
  rotation,  ///< steady spin omega, no squeeze
  squeeze,   ///< pure approach along the line of centres at the rate d eps / dt > 0, no spin
};

enum class BearingMethod {
  grid,           ///< finite width: ReynoldsGridSolver
  short_bearing,  ///< Ocvirk closed form (half-Sommerfeld only)
  long_bearing,   ///< Sommerfeld closed form (half-Sommerfeld only)
  table,          ///< the grid's film tabulated over eps (FilmTable; half-Sommerfeld only)
};

}  // namespace clearjoint::lubrication

/// Keys "rotation", "squeeze": what every front end reads and writes.
template <>
struct clearjoint::geometry::EnumTable<clearjoint::lubrication::BearingMotion> {
  using M = clearjoint::lubrication::BearingMotion;
  static constexpr std::string_view type_name = "BearingMotion";
  static constexpr auto entries = std::to_array({
      named_entry(M::rotation, "rotation", "steady spin, no squeeze"),
      named_entry(M::squeeze, "squeeze", "pure approach along the line of centres, no spin"),
  });
};
static_assert(clearjoint::geometry::entries_in_code_order<clearjoint::lubrication::BearingMotion>());

/// Keys "grid", "short", "long": the model files' and the command line's established spellings.
template <>
struct clearjoint::geometry::EnumTable<clearjoint::lubrication::BearingMethod> {
  using M = clearjoint::lubrication::BearingMethod;
  static constexpr std::string_view type_name = "BearingMethod";
  static constexpr auto entries = std::to_array<EnumEntry<M>>({
      {M::grid, "grid", "grid", "finite width, Reynolds equation on a grid"},
      {M::short_bearing, "short_bearing", "short", "short bearing (Ocvirk)"},
      {M::long_bearing, "long_bearing", "long", "long bearing (Sommerfeld)"},
      {M::table, "table", "table", "finite width, the grid's film tabulated over eps"},
  });
};
static_assert(clearjoint::geometry::entries_in_code_order<clearjoint::lubrication::BearingMethod>());

namespace clearjoint::lubrication {

/// The key of the value's entry in its table.
std::string_view to_string(BearingMotion motion) noexcept;
std::string_view to_string(BearingMethod method) noexcept;

/// The cavitation model a front end takes when none is named: mass-conserving for the grid (the
/// handbook's set-up, Raimondi & Boyd, below), half-Sommerfeld, the only one they have, for the
/// closed forms and the table.
CavitationModel default_cavitation(BearingMethod method) noexcept;

struct BearingCharacteristicsQuery {
  double eccentricity_ratio = 0.0;  ///< eps in [0, 1)
  double width_ratio = 1.0;         ///< B / D > 0
  BearingMotion motion = BearingMotion::rotation;
  CavitationModel cavitation = CavitationModel::mass_conserving;
  BearingMethod method = BearingMethod::grid;
  ReynoldsGridOptions grid = {};
};

/// What bearing handbooks tabulate. With the mass-conserving model the bearing is fed at ambient
/// pressure along the thickest film (an axial line at psi = pi), the convention of Raimondi &
/// Boyd (ASLE Trans. 1, 1958) whose tables docs/lubrication.md compares against.
struct BearingCharacteristics {
  /// So = F psi^2 / (B D eta omega), psi = c / R the relative clearance (for squeeze, d eps / dt
  /// in place of omega). Raimondi & Boyd's S = (R/c)^2 eta N / P (N in rev/s, P = F / (B D)) is
  /// 1 / (2 pi So).
  double sommerfeld_number = 0.0;
  double attitude_angle = 0.0;  ///< beta, rad: from the load to the line of centres
  /// 2 pi Q_s / (R c omega B), Raimondi & Boyd's side-flow variable Q_s / (R c N B) (for
  /// squeeze, d eps / dt in place of omega).
  double side_flow_variable = 0.0;
  double max_pressure_ratio = 0.0;  ///< p_max / (F / (B D)), the reciprocal of R & B's P / p_max
  int iterations = 0;               ///< linear solves (grid only)
  bool converged = true;            ///< grid only: see FilmLoad::converged
};

/// Throws geometry::InvalidInput naming the field for eps outside {0} U [kSmallestEccentricityRatio,
/// 1), a width ratio outside [kSmallestWidthRatio, kLargestWidthRatio], a closed form or the table
/// asked for the mass-conserving model, or a bad grid (too fine a one: validate(ReynoldsGridOptions)).
/// The closed forms' outputs are exact to kClosedFormRelativeError for every accepted input.
BearingCharacteristics bearing_characteristics(const BearingCharacteristicsQuery& query);

/// A query's choices as a front end receives them: names (the tables' keys), and the grid's size.
struct BearingCharacteristicsNames {
  std::string motion = "rotation";
  std::string method = "grid";
  std::optional<std::string> cavitation;  ///< nullopt: default_cavitation(method)
  /// (N_theta, N_z); nullopt: ReynoldsGridOptions' defaults.
  std::optional<std::pair<int, int>> grid;
  /// Solve a grid above the solver's cost limits (ReynoldsGridOptions::allow_large_grid).
  bool allow_large_grid = false;
};

/// The query for eps, B / D and the named choices: what the command line and Python both call.
/// Throws geometry::InvalidInput naming the field and its value for an unknown name
/// ("motion = 'spin': unknown (known: rotation, squeeze)") or a grid below the solver's minima
/// ("grid = 1x1: options.circumferential_cells = 1: must be at least 8"); eps and B / D are
/// checked by bearing_characteristics.
BearingCharacteristicsQuery query_from_names(double eccentricity_ratio, double width_ratio,
                                             const BearingCharacteristicsNames& names);

/// The relative error of every output of the closed forms (short, long; rotation or squeeze)
/// for every accepted eps, 1 - 2^-53 included: 1e-14. Their forms keep 1 - eps^2 (formed as
/// (1 - eps)(1 + eps), 1 - eps exact) out of every difference (long_bearing.cpp,
/// short_bearing.cpp), so each output is a few dozen roundings of 2^-53 (1.1e-16) each plus the
/// peak search's 1e-15 (short_bearing.cpp): at most about 5e-15; measured 8e-16 at worst against
/// a 50-digit evaluation (test_bearing_characteristics.cpp), a margin of 12.
inline constexpr double kClosedFormRelativeError = 1e-14;
/// The width ratios B / D accepted: [1e-50, 1e50]. So grows as (B/D)^2 and (1 - eps^2)^-2 <=
/// 2^104 = 2e31, the short bearing's force as (B/D)^3 / c^2 (c = 1e-4 R) times 1 / s^5 <= 1e39:
/// at 1e50 the largest intermediate is 1e197; at 1e-50 the smallest, eps B^3 / c^2 with
/// eps >= 1e-100, is 5e-243; both far inside the doubles' normal range (2.2e-308 to 1.8e308), so
/// nothing over- or underflows. Real bearings lie within [0.01, 100].
inline constexpr double kSmallestWidthRatio = 1e-50;
inline constexpr double kLargestWidthRatio = 1e50;
/// The smallest non-zero eps accepted: 1e-100. Forces and flows are proportional to eps as
/// eps -> 0; below it, with the narrowest width, the side flow R B c eps would leave the normal
/// range (1e-100 x 1e-50 x 1e-4 = 1e-154 times scales near 1 stays inside). eps = 0 is exact.
inline constexpr double kSmallestEccentricityRatio = 1e-100;

/// The relative clearance c / R of the grid's bearing. The characteristics are independent of it
/// to first order; the film thickness' exact geometry differs from h = c (1 - eps cos psi) by
/// O(c / R) relatively, so 1e-4 keeps that effect below the grid's own error.
inline constexpr double kCharacteristicsRelativeClearance = 1e-4;

}  // namespace clearjoint::lubrication
