// SPDX-License-Identifier: BSD-3-Clause
#include "joint_film.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "clearjoint/lubrication/film_thickness.hpp"
#include "clearjoint/lubrication/long_bearing.hpp"
#include "clearjoint/lubrication/short_bearing.hpp"

namespace clearjoint::dynamics {

namespace {

/// How aligned a film must be for the table (made for an aligned journal) to stand for the grid:
/// the journal axis' offsets at the film's two ends may differ by this fraction of c, and the
/// ends' squeeze from a tilting rate by this fraction of the centre's velocity across the film
/// and the spin's surface speed. The load changes by about as much relatively, 1e-6, far below
/// the table's error bound (FilmTable::error_bound); a planar model is aligned to rounding.
constexpr double kTableAlignment = 1e-6;

/// A unit vector perpendicular to `axis` (unit): the world axis least aligned with it, projected.
Vector3 any_perpendicular(const Vector3& axis) {
  Eigen::Index least_aligned = 0;
  axis.cwiseAbs().minCoeff(&least_aligned);
  const Vector3 e = Vector3::Unit(least_aligned);
  return (e - e.dot(axis) * axis).normalized();
}

}  // namespace

JointFilm::JointFilm(const JointLubrication& lubrication, const geometry::JointDimensions& dimensions)
    : lubrication_(lubrication), dimensions_(dimensions) {
  if (lubrication_.method == FilmMethod::grid || lubrication_.method == FilmMethod::table) {
    lubrication::ReynoldsGridOptions options;
    options.circumferential_cells = lubrication_.circumferential_cells;
    options.axial_cells = lubrication_.axial_cells;
    options.allow_large_grid = lubrication_.allow_large_grid;
    options.cavitation = lubrication_.cavitation;
    grid_.emplace(options);
  }
}

JointFilmState JointFilm::evaluate(const geometry::PartPose& bearing,
                                   const geometry::PartPose& journal,
                                   const std::optional<Vector3>& groove_W,
                                   const lubrication::RelativeMotion& motion, FilmDetail detail) {
  const Vector3 axis_W = bearing.axis_W.normalized();
  lubrication::FilmGeometry film = lubrication::describe_film(
      dimensions_, bearing, journal, groove_W ? *groove_W : any_perpendicular(axis_W));
  JointFilmState state;
  const lubrication::ThinnestFilm thinnest = lubrication::thinnest_film(film);
  const double c = film.radial_clearance;
  const double z_mid = 0.5 * (film.z_low + film.z_high);
  const Vector3 e_W = lubrication::journal_offset(film, z_mid);  // line of centres, mid-plane
  state.min_thickness = thinnest.thickness;
  state.eccentricity_ratio = e_W.norm() / c;
  state.weight = film_weight(lubrication_, thinnest.thickness);
  state.regime = film_regime(state.weight);
  if (state.regime == FilmRegime::dry) {
    state.attitude_angle = state.max_pressure = std::numeric_limits<double>::quiet_NaN();
    return state;
  }
  ++statistics_.solves;

  // The velocity across the film of the journal axis' point in the mid-plane, from the
  // library's squeeze rate dh/dt = -q' . n(theta) at two perpendicular normals.
  const Vector3 n0 = film.theta_zero_W, n90 = film.theta_quarter_W;
  const Vector3 q_W = -(lubrication::film_thickness_rate(film, motion, 0.0, z_mid) * n0 +
                        lubrication::film_thickness_rate(film, motion, 0.5 * std::numbers::pi, z_mid) * n90);
  // The line of centres' direction; at exactly eps = 0 it is undefined and the film depends on
  // the approach only: take its direction (a closed form then sees pure squeeze, eps' = |q'| / c).
  Vector3 e_hat = n0;
  if (e_W.norm() > 0.0) {
    e_hat = e_W.normalized();
  } else if (q_W.norm() > 0.0) {
    e_hat = q_W.normalized();
  }
  const Vector3 t_hat = axis_W.cross(e_hat);

  // The table, where it stands for the grid: an aligned journal in a film without a groove,
  // within the table's eps (film_table.hpp).
  std::optional<lubrication::PlanarFilmLoad> tabulated;
  if (lubrication_.method == FilmMethod::table && !groove_W) {
    const double spin = lubrication::journal_spin(film, motion);
    const Vector3 tilt_rate_W = motion.omega_BJ_W - motion.omega_BJ_W.dot(axis_W) * axis_W;
    const bool aligned =
        (lubrication::journal_offset(film, film.z_high) - lubrication::journal_offset(film, film.z_low)).norm() <=
            kTableAlignment * c &&
        tilt_rate_W.norm() * film.width() <= kTableAlignment * (q_W.norm() + c * std::abs(spin));
    // One table per joint, for the film of the whole journal inside its bearing (Lj < Li): a
    // journal partly out of its bearing, whose film is narrower and changes with every step,
    // is solved by the grid rather than tabulated again at each width.
    const double full_width = std::min(dimensions_.journal_length, dimensions_.bearing_length);
    const bool whole = std::abs(film.width() - full_width) <= kTableAlignment * full_width;
    if (aligned && whole) {
      const lubrication::FilmTableKey key{film.journal_radius, c, full_width, lubrication_.circumferential_cells,
                                          lubrication_.axial_cells, lubrication_.cavitation};
      if (!table_ || !(table_->key() == key)) table_ = lubrication::FilmTable::shared(key);
      lubrication::PlanarFilmState planar;
      planar.eccentricity_ratio = state.eccentricity_ratio;
      planar.eccentricity_ratio_rate = q_W.dot(e_hat) / c;
      planar.line_of_centres_rate = e_W.norm() > 0.0 ? q_W.dot(t_hat) / e_W.norm() : 0.0;
      planar.journal_spin = spin;
      tabulated = table_->load(planar, lubrication_.viscosity);
    }
    if (!tabulated) ++statistics_.table_fallbacks;
  }

  Vector3 force_W = Vector3::Zero(), moment_W = Vector3::Zero();
  if (tabulated) {
    force_W = tabulated->radial * e_hat + tabulated->tangential * t_hat;
    // Through the journal's axis at the mid-plane, as the grid's pressures act: its moment about P_j.
    const Vector3 p_WA = film.p_WB + z_mid * axis_W + e_W;
    moment_W = (p_WA - film.p_WJ).cross(force_W);
    state.max_pressure = tabulated->max_pressure;
  } else if (grid_) {
    if (!groove_W) {
      // theta = 0 on the line of centres: the warm start then turns with the load as the
      // journal orbits (reynolds_grid.hpp).
      film.theta_zero_W = e_hat;
      film.theta_quarter_W = t_hat;
    }
    const lubrication::OilSupply supply =
        groove_W ? lubrication::OilSupply{lubrication::OilSupply::Kind::axial_groove, *groove_W,
                                          lubrication_.supply_pressure}
                 : lubrication::OilSupply{};
    const lubrication::FilmLoad load =
        grid_->solve(film, motion, lubrication::Lubricant{lubrication_.viscosity}, supply);
    force_W = load.force_W;
    moment_W = load.moment_W;
    state.max_pressure = load.max_pressure;
    statistics_.linear_solves += load.iterations;
    if (!load.converged) ++statistics_.not_converged;
  } else {
    lubrication::PlanarFilmState planar;
    planar.eccentricity_ratio = state.eccentricity_ratio;
    planar.eccentricity_ratio_rate = q_W.dot(e_hat) / c;
    planar.line_of_centres_rate = e_W.norm() > 0.0 ? q_W.dot(t_hat) / e_W.norm() : 0.0;
    planar.journal_spin = lubrication::journal_spin(film, motion);
    const lubrication::PlanarBearing planar_bearing{film.journal_radius, film.width(), c};
    const lubrication::PlanarFilmLoad load =
        lubrication_.method != FilmMethod::short_bearing
            ? lubrication::long_bearing_load(planar_bearing, planar, lubrication_.viscosity)
        : detail == FilmDetail::force
            ? lubrication::short_bearing_force(planar_bearing, planar, lubrication_.viscosity)
            : lubrication::short_bearing_load(planar_bearing, planar, lubrication_.viscosity);
    force_W = load.radial * e_hat + load.tangential * t_hat;
    // Acting through the journal's axis at the mid-plane: its moment about P_j.
    const Vector3 p_WA = film.p_WB + z_mid * axis_W + e_W;
    moment_W = (p_WA - film.p_WJ).cross(force_W);
    state.max_pressure = load.max_pressure;
  }
  const double radial = force_W.dot(e_hat), tangential = force_W.dot(t_hat);
  state.attitude_angle =
      (radial == 0.0 && tangential == 0.0) ? 0.0 : std::atan2(tangential, -radial);
  state.force_on_journal_W = state.weight * force_W;
  state.moment_on_journal_W = state.weight * moment_W;
  state.power = state.force_on_journal_W.dot(motion.v_BJ_W) +
                state.moment_on_journal_W.dot(motion.omega_BJ_W);
  return state;
}

}  // namespace clearjoint::dynamics
