// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The finite-width film at closed-form cost: the ReynoldsGridSolver's half-Sommerfeld film on an
/// aligned journal, tabulated once per bearing over the eccentricity ratio and interpolated.
///
/// For half-Sommerfeld the grid solves one linear system whose matrix depends on the film's shape
/// (eps) only and whose right-hand side is linear in the motion, then sets negative pressures to
/// ambient. The motion of an aligned journal enters through three rates: its spin omega, and the
/// velocity of its centre along the line of centres (c eps') and across it (c eps phi', the
/// whirl). The table stores, at each of kTableEccentricityNodes values of eps, the grid's
/// unclipped nodal pressures for each unit rate; a call interpolates the three fields to its eps
/// (cubic convolution, Keys, IEEE Trans. ASSP 29, 1981: third order, C1, four nodes), superposes
/// them with its rates, clips and integrates exactly as the grid does. So the squeeze-to-rotation
/// ratio and the whirl are exact (the table has no axis for them), and the only approximation is
/// the interpolation in eps of smooth full-film fields. The fields are interpolated on nodes
/// uniform in log(1 - eps), each scaled by (1 - eps)^2.5, the growth of the squeeze film's
/// pressure towards the wall, so that they vary slowly. Boost.Math's interpolators are 1-D over
/// one function: here one set of weights serves the 3 x N_theta x (N_z - 1) nodal values, which
/// a per-value spline object would refit or store apart.
///
/// The table's error against the grid is measured when it is built, between every pair of eps
/// nodes (where an interpolant strays furthest) over kTableErrorDirections motions, and reported
/// as FilmTable::error_bound. Outside its domain (eps above kTableLargestEccentricityRatio, a
/// tilted journal, an oil groove, the mass-conserving model) the caller solves the grid.

#include <memory>
#include <optional>
#include <vector>

#include "clearjoint/lubrication/film_conditions.hpp"
#include "clearjoint/lubrication/planar_film.hpp"

namespace clearjoint::lubrication {

/// What a table is built for: the film's sizes and the grid it reproduces. Two keys equal in
/// every field give the same table (FilmTable::shared returns the one it built).
struct FilmTableKey {
  double journal_radius = 0.0;    ///< R, m
  double radial_clearance = 0.0;  ///< c, m
  double width = 0.0;             ///< B, m
  int circumferential_cells = 48;
  int axial_cells = 12;
  CavitationModel cavitation = CavitationModel::half_sommerfeld;
  bool operator==(const FilmTableKey&) const = default;
};

/// The table's reach in eps: [0, 0.98], a film down to 0.02 c (2 um in the paper's joint, whose
/// lubricated model hands over to dry contact there). Beyond, the grid is solved.
inline constexpr double kTableLargestEccentricityRatio = 0.98;
/// Nodes uniform in log(1 - eps) over [0, kTableLargestEccentricityRatio]: 3 grid solves each to
/// build; 49 keep the measured error (FilmTable::error_bound) far below kTableErrorTarget on the
/// 48 x 12 grid (docs/lubrication.md).
inline constexpr int kTableEccentricityNodes = 129;
/// The motions the error is measured for between each pair of nodes: spin and squeeze mixed at
/// this many angles around the circle (pure spin, pure squeeze, approach and separation), plus
/// the same with whirl.
inline constexpr int kTableErrorDirections = 16;
/// The largest relative error of the force (|F_table - F_grid| / |F_grid|) a table is built to
/// keep, from issue 49: a film force within 0.5 % of the grid's along a run. The table's own
/// measured bound is FilmTable::error_bound.
inline constexpr double kTableErrorTarget = 5e-3;

class FilmTable {
 public:
  /// Builds the table: 3 kTableEccentricityNodes grid solves, then 2 kTableErrorDirections
  /// between each pair of nodes to measure error_bound. Throws geometry::InvalidInput naming the field
  /// for bad sizes (validate(PlanarBearing...)), a grid the solver refuses, or the mass-conserving
  /// model (its load depends on the groove's position and on the spin and whirl apart).
  explicit FilmTable(const FilmTableKey& key);

  /// The table for `key`, built on first use and kept for the life of the process (thread-safe).
  static std::shared_ptr<const FilmTable> shared(const FilmTableKey& key);

  /// The load for the aligned journal's state, or nullopt outside the table's eps range (the
  /// caller then solves the grid). state must be finite (validate(PlanarBearing...)); radial
  /// and tangential are along the line of centres e_hat and t_hat = a_B x e_hat (planar_film.hpp).
  std::optional<PlanarFilmLoad> load(const PlanarFilmState& state, double viscosity) const;

  /// The largest relative force error |F_table - F_grid| / |F_grid| measured against the grid
  /// midway (in log(1 - eps)) between every pair of nodes.
  double error_bound() const noexcept { return error_bound_; }
  /// The same per interval between neighbouring nodes: [e] for the interval from node e to
  /// e + 1, whose midpoint is at eps = interval_eccentricity(e).
  const std::vector<double>& interval_errors() const noexcept { return interval_errors_; }
  static double interval_eccentricity(int interval);
  const FilmTableKey& key() const noexcept { return key_; }

 private:
  double growth_at(int node) const;

  FilmTableKey key_;
  int half_rows_ = 0;   ///< the rows kept of each column: the half nearer z_low, the middle one included
  int node_count_ = 0;  ///< N_theta half_rows_ pressure nodes
  /// At each eps node, three fields of node_count_ pressures (Pa for unit viscosity and a unit
  /// rate: omega = 1 rad/s, eps' = 1 1/s, eps phi' = 1 1/s), scaled by (1 - eps)^2.5:
  /// fields_[(e * 3 + field) * node_count_ + k].
  std::vector<double> fields_;
  /// Per pressure node: -area n . e_hat, -area n . t_hat (m^2), times 2 for a row standing for
  /// its mirror too.
  std::vector<double> radial_area_, tangential_area_;
  /// Per eps node and column: the side flow through both end faces per unit pressure of the row
  /// next to them, times the viscosity (m^3 / (Pa s)): [e * N_theta + i].
  std::vector<double> side_flow_weight_;
  double error_bound_ = 0.0;
  std::vector<double> interval_errors_;
};

}  // namespace clearjoint::lubrication
