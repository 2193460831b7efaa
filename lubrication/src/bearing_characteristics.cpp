// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/lubrication/bearing_characteristics.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/lubrication/film_table.hpp"
#include "clearjoint/lubrication/long_bearing.hpp"
#include "clearjoint/lubrication/reynolds_grid.hpp"
#include "clearjoint/lubrication/short_bearing.hpp"
#include "refuse.hpp"

namespace clearjoint::lubrication {

namespace {

/// The bearing's length exceeds the journal's (the film's width) by this fraction: any amount
/// works, the film is the journal's length (film_thickness.hpp); JointDimensions needs Li > Lj.
constexpr double kBearingLengthMargin = 1e-3;

/// The value whose key is `name`, or InvalidInput "<field> = '<name>': unknown (known: ...)".
template <geometry::TabledEnum E>
E named(std::string_view name, const char* field) {
  if (const std::optional<E> value = geometry::from_string<E>(name)) return *value;
  throw geometry::InvalidInput(field, " = '" + std::string(name) + "': unknown (known: " +
                                          geometry::known_keys<E>() + ")");
}

using detail::require;

}  // namespace

std::string_view to_string(BearingMotion motion) noexcept { return geometry::key_of(motion); }

std::string_view to_string(BearingMethod method) noexcept { return geometry::key_of(method); }

CavitationModel default_cavitation(BearingMethod method) noexcept {  // table: half-Sommerfeld
  return method == BearingMethod::grid ? CavitationModel::mass_conserving
                                       : CavitationModel::half_sommerfeld;
}

BearingCharacteristicsQuery query_from_names(double eccentricity_ratio, double width_ratio,
                                             const BearingCharacteristicsNames& names) {
  BearingCharacteristicsQuery query;
  query.eccentricity_ratio = eccentricity_ratio;
  query.width_ratio = width_ratio;
  query.motion = named<BearingMotion>(names.motion, "motion");
  query.method = named<BearingMethod>(names.method, "method");
  query.cavitation = names.cavitation ? named<CavitationModel>(*names.cavitation, "cavitation")
                                      : default_cavitation(query.method);
  query.grid.allow_large_grid = names.allow_large_grid;
  if (names.grid) {
    query.grid.circumferential_cells = names.grid->first;
    query.grid.axial_cells = names.grid->second;
    try {
      validate(query.grid);  // the solver's own minima, under the name the caller used
    } catch (const geometry::InvalidInput& e) {
      throw geometry::InvalidInput("grid = " + std::to_string(names.grid->first) + "x" +
                                   std::to_string(names.grid->second) + ": " + e.what());
    }
  }
  return query;
}

BearingCharacteristics bearing_characteristics(const BearingCharacteristicsQuery& query) {
  const double eps = query.eccentricity_ratio;
  require(eps >= 0.0 && eps < 1.0, "eccentricity_ratio", eps,
          "must be in [0, 1) (at 1 the journal touches the wall)");
  require(eps == 0.0 || eps >= kSmallestEccentricityRatio, "eccentricity_ratio", eps,
          "must be 0 or at least 1e-100 (below, the outputs, proportional to it, underflow)");
  require(query.width_ratio >= kSmallestWidthRatio && query.width_ratio <= kLargestWidthRatio,
          "width_ratio", query.width_ratio,
          "must be in [1e-50, 1e50] (beyond, the outputs over- or underflow)");
  if (query.method == BearingMethod::grid || query.method == BearingMethod::table) {
    validate_grid_width_ratio(query.width_ratio, "width_ratio");
  }
  if (query.method != BearingMethod::grid &&
      query.cavitation != CavitationModel::half_sommerfeld) {
    throw geometry::InvalidInput(
        "cavitation = mass_conserving: the closed forms (short, long) and the table are "
        "half-Sommerfeld only; use method = grid");
  }
  // Unit journal radius, unit viscosity, unit rate: the results are non-dimensional.
  const double radius = 1.0;
  const double diameter = 2.0 * radius;
  const double clearance = kCharacteristicsRelativeClearance * radius;
  const double width = query.width_ratio * diameter;
  const double rate = 1.0;
  const bool rotation = query.motion == BearingMotion::rotation;

  double force_radial = 0.0, force_tangential = 0.0, side_flow = 0.0, max_pressure = 0.0;
  BearingCharacteristics result;
  if (query.method == BearingMethod::table) {
    validate(query.grid);
    const auto table = FilmTable::shared({radius, clearance, width, query.grid.circumferential_cells,
                                          query.grid.axial_cells, query.cavitation});
    PlanarFilmState state;
    state.eccentricity_ratio = eps;
    (rotation ? state.journal_spin : state.eccentricity_ratio_rate) = rate;
    const std::optional<PlanarFilmLoad> load = table->load(state, 1.0);
    if (!load) {
      detail::refuse("eccentricity_ratio", eps, "beyond the table's reach (0.98, kTableLargestEccentricityRatio); use method = grid");
    }
    force_radial = load->radial;
    force_tangential = load->tangential;
    side_flow = load->side_flow;
    max_pressure = load->max_pressure;
  } else if (query.method == BearingMethod::grid) {
    validate(query.grid);
    geometry::JointDimensions dimensions{radius + clearance, width * (1.0 + kBearingLengthMargin),
                                         radius, width};
    geometry::PartPose bearing;  // at the origin, axis z
    geometry::PartPose journal;
    journal.p_WP = Vector3(eps * clearance, 0.0, 0.0);  // line of centres along +x
    RelativeMotion motion;
    if (rotation) {
      motion.omega_BJ_W = Vector3(0.0, 0.0, rate);
    } else {
      motion.v_BJ_W = Vector3(rate * clearance, 0.0, 0.0);
    }
    OilSupply supply;
    if (query.cavitation == CavitationModel::mass_conserving) {
      supply.kind = OilSupply::Kind::axial_groove;  // fed along the thickest film, psi = pi
      supply.groove_direction_W = Vector3(-1.0, 0.0, 0.0);
    }
    ReynoldsGridOptions options = query.grid;
    options.cavitation = query.cavitation;
    ReynoldsGridSolver solver(options);
    const FilmLoad load =
        solver.solve(dimensions, bearing, journal, motion, Lubricant{1.0}, supply);
    force_radial = load.force_W.x();
    force_tangential = load.force_W.y();
    side_flow = load.side_flow;
    max_pressure = load.max_pressure;
    result.iterations = load.iterations;
    result.converged = load.converged;
  } else {
    const PlanarBearing bearing{radius, width, clearance};
    PlanarFilmState state;
    state.eccentricity_ratio = eps;
    (rotation ? state.journal_spin : state.eccentricity_ratio_rate) = rate;
    const PlanarFilmLoad load = query.method == BearingMethod::short_bearing
                                    ? short_bearing_load(bearing, state, 1.0)
                                    : long_bearing_load(bearing, state, 1.0);
    force_radial = load.radial;
    force_tangential = load.tangential;
    side_flow = load.side_flow;
    max_pressure = load.max_pressure;
  }
  const double force = std::hypot(force_radial, force_tangential);
  const double psi = clearance / radius;
  result.sommerfeld_number = force * psi * psi / (width * diameter * rate);
  result.attitude_angle = force > 0.0 ? std::atan2(force_tangential, -force_radial) : 0.0;
  result.side_flow_variable = 2.0 * std::numbers::pi * side_flow / (radius * clearance * rate * width);
  result.max_pressure_ratio = force > 0.0 ? max_pressure / (force / (width * diameter)) : 0.0;
  return result;
}

}  // namespace clearjoint::lubrication
