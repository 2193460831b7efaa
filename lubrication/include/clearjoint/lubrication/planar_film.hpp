// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The aligned journal of the closed forms (short_bearing.hpp, long_bearing.hpp): its state in
/// the bearing's plane, and the load its film carries.
///
/// Notation (docs/lubrication.md): e = eps c is the eccentricity, phi the angle of the line of
/// centres (from the bearing's centre to the journal's), psi = theta - phi the angle from the
/// line of centres, so h = c (1 - eps cos psi), thinnest at psi = 0. e_hat is the line of
/// centres' unit direction and t_hat = a_B x e_hat, 90 degrees ahead of it in the positive sense.

namespace clearjoint::lubrication {

/// Sizes of an aligned bearing.
struct PlanarBearing {
  double radius = 0.0;            ///< journal radius R (m)
  double width = 0.0;             ///< film width B along the axis (m)
  double radial_clearance = 0.0;  ///< c (m)
};

/// The aligned journal's state, relative to the bearing (rates in the bearing body's frame).
struct PlanarFilmState {
  double eccentricity_ratio = 0.0;       ///< eps = e / c, in [0, 1)
  double eccentricity_ratio_rate = 0.0;  ///< d eps / dt, 1/s (> 0: approaching the wall)
  double line_of_centres_rate = 0.0;     ///< d phi / dt, rad/s (whirl)
  double journal_spin = 0.0;             ///< omega, rad/s, positive about a_B
};

/// The film's load on the journal.
struct PlanarFilmLoad {
  double radial = 0.0;      ///< F . e_hat, N (< 0: pushes the journal back towards the centre)
  double tangential = 0.0;  ///< F . t_hat, N
  double magnitude = 0.0;   ///< |F|, N
  /// beta, the angle from the load the journal carries (W = -F) to the line of centres, rad,
  /// positive in the positive sense about a_B: atan2(tangential, -radial). For a journal
  /// spinning positively the line of centres leads the load (beta > 0); reversing the spin
  /// mirrors it. 0 for a zero load.
  double attitude_angle = 0.0;
  double max_pressure = 0.0;  ///< largest gauge pressure, Pa
  double side_flow = 0.0;     ///< m^3/s leaving through both ends (0 for the long bearing)
};

/// Throw geometry::InvalidInput for non-positive or non-finite sizes, a clearance not smaller
/// than the radius, eps outside [0, 1), a non-finite rate, or a bad viscosity.
void validate(const PlanarBearing& bearing, const PlanarFilmState& state, double viscosity);

}  // namespace clearjoint::lubrication
