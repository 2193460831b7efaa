// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/joint_lubrication.hpp"

#include <algorithm>
#include <cmath>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/geometry/model/enum_table.hpp"

namespace clearjoint::dynamics {

FilmMethod film_method_from_string(std::string_view name, std::string_view field) {
  if (const auto method = geometry::from_string<FilmMethod>(name)) return *method;
  throw ModelError(std::string(field) + " = \"" + std::string(name) +
                   "\": unknown film method (known: " +
                   geometry::known_keys<FilmMethod>() + ")");
}

lubrication::CavitationModel cavitation_model_from_string(std::string_view name,
                                                          std::string_view field) {
  if (const auto model = geometry::from_string<lubrication::CavitationModel>(name)) return *model;
  throw ModelError(std::string(field) + " = \"" + std::string(name) +
                   "\": unknown cavitation model (known: " +
                   geometry::known_keys<lubrication::CavitationModel>() + ")");
}

namespace {

/// ModelError "<field> = <value>: must be in [low, high] <unit> (<why>)" unless low <= value <=
/// high (and finite); `open_high` makes the upper end excluded.
void require_in(const std::string& field, double value, double low, double high, bool open_high,
                const std::string& unit_and_why) {
  require_finite(field, value);
  if (value >= low && (open_high ? value < high : value <= high)) return;
  throw ModelError(field, " = " + format_shortest(value) + ": must be in [" + format_shortest(low) + ", " +
                              format_shortest(high) + (open_high ? ")" : "]") + unit_and_why);
}

/// One of the film library's validate()s (its one check of that description) under `name`, its
/// InvalidInput reported as the dynamics' ModelError with the same field path and message.
template <class Description>
void validate_in_film_library(const Description& description, const std::string& name) {
  try {
    lubrication::validate(description, name.c_str());
  } catch (const geometry::InvalidInput& e) {
    throw ModelError(e.field_path(), e.detail());
  }
}

}  // namespace

void validate(const JointLubrication& l, const std::string& name, double radial_clearance) {
  validate_in_film_library(lubrication::Lubricant{l.viscosity}, name);
  require_in(name + ".viscosity", l.viscosity, kSmallestViscosity, kLargestViscosity, false,
             " Pa s (gases to the stiffest greases)");
  require_positive(name + ".film_thickness_limit", l.film_thickness_limit);
  require_positive(name + ".transition_width", l.transition_width);
  if (std::isfinite(radial_clearance) && radial_clearance > 0.0) {
    const double smallest = kSmallestFilmLengthOfClearance * radial_clearance;
    require_in(name + ".film_thickness_limit", l.film_thickness_limit, smallest, radial_clearance,
               true, " m (from 1e-6 of the radial clearance to below it: the film is never thicker)");
    require_in(name + ".transition_width", l.transition_width, smallest, radial_clearance, false,
               " m (from 1e-6 of the radial clearance to the clearance)");
  }
  if (l.method == FilmMethod::grid || l.method == FilmMethod::table) {  // the table's grid too
    lubrication::ReynoldsGridOptions grid;
    grid.circumferential_cells = l.circumferential_cells;
    grid.axial_cells = l.axial_cells;
    grid.allow_large_grid = l.allow_large_grid;
    try {
      lubrication::validate(grid);  // the solver's own minima and cost limits
    } catch (const geometry::InvalidInput& e) {
      throw ModelError(name + ".grid", " = [" + std::to_string(l.circumferential_cells) + ", " +
                       std::to_string(l.axial_cells) + "]: " + e.what());
    }
  }
  const bool mass_conserving = l.cavitation == lubrication::CavitationModel::mass_conserving;
  if (mass_conserving && l.method != FilmMethod::grid) {
    throw ModelError(name + ".cavitation", " = \"mass_conserving\": method " +
                     std::string(lubrication::to_string(l.method)) + " is half-Sommerfeld only; use method grid");
  }
  if (mass_conserving && !l.groove_direction_B) {
    throw ModelError(name + ".groove_direction", " is missing: a mass-conserving film fed only at "
                     "its ends drains (docs/lubrication.md); give the oil groove's direction");
  }
  if (l.groove_direction_B) require_nonzero(name + ".groove_direction", *l.groove_direction_B);
  lubrication::OilSupply supply;  // its groove direction is the body frame's, checked above
  supply.supply_pressure = l.supply_pressure;
  validate_in_film_library(supply, name);
  require_in(name + ".supply_pressure", l.supply_pressure, 0.0, kLargestSupplyPressure, false,
             " Pa (a gauge pressure; 1 GPa is above any oil feed)");
}

double film_weight(const JointLubrication& l, double min_thickness) noexcept {
  const double s = std::clamp((min_thickness - l.film_thickness_limit) / l.transition_width, 0.0, 1.0);
  return s * s * (3.0 - 2.0 * s);  // smoothstep: 0 and 1 with zero slope at both ends
}

FilmRegime film_regime(double weight) noexcept {
  if (weight <= 0.0) return FilmRegime::dry;
  if (weight >= 1.0) return FilmRegime::film;
  return FilmRegime::blend;
}

}  // namespace clearjoint::dynamics
