// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// What a film solution gives the journal, and how far it can be trusted.

#include "clearjoint/lubrication/film_thickness.hpp"

namespace clearjoint::lubrication {

/// The film's action on the journal (the bearing receives the opposite force, and the opposite
/// moment about the same point). Gauge pressures: the ambient pressure acting all round cancels.
struct FilmLoad {
  Vector3 force_W = Vector3::Zero();   ///< on the journal, N, in W
  Vector3 moment_W = Vector3::Zero();  ///< on the journal about its centre P_j, N m, in W
  double max_pressure = 0.0;           ///< largest gauge pressure, Pa
  double max_pressure_theta = 0.0;     ///< where (rad, the film's theta)
  double max_pressure_z = 0.0;         ///< where (m, the film's z)
  double side_flow = 0.0;              ///< m^3/s leaving through both ends of the film
  double cavitated_fraction = 0.0;     ///< share of the film's nodes at or below ambient pressure
  ThinnestFilm thinnest;               ///< h_min and where it is
  int iterations = 0;                  ///< linear solves used (1 for half-Sommerfeld)
  /// For the mass-conserving model: the active set (which nodes carry pressure) stopped changing
  /// and the residual met the tolerance. When false, the load is that of the last iterate.
  bool converged = true;
};

}  // namespace clearjoint::lubrication
